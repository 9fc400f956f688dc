"""How each grasp of an answer holds its object, in terms a user can check
against the scene: the family, the pair of faces the fingers close on, the
width between them, a side grasp's pitch and the hand's opening; for the
planar robot, the contact angle of its suction. Written to solution.json's
`grasps` and printed by `solve` (docs/formats.md, "solution.json")."""

from __future__ import annotations

import math

from tampcli.optimize import grasp_families as F


def faces(info, psi: float) -> str:
    """The object's faces the fingers close on: "±x" or "±y" of its own frame
    (grasp_families.closing_width's choice), "round" for a cylinder or sphere."""
    if info.disk:
        return "round"
    return "±y" if abs(math.cos(psi)) > 0.5 else "±x"


def grasp_report(problem, choices: dict, keyframes) -> tuple[dict, ...]:
    """One entry per grasp step of `problem` (lowered, its hand as planned), as
    `choices` (step -> values.GripChoice) and `keyframes` (values.Keyframes: a
    side grasp's pitch, a suction's contact angle) hold it."""
    out = []
    for step in problem.steps:
        if step.kind.fingers is not True:
            continue
        choice = choices.get(step.index)
        t = keyframes.grip.get(step.index)
        entry = {"action": step.name, "object": step.obj}
        if problem.planar:
            entry.update(family="suction", contact_angle=None if t is None else float(t))
        elif choice is not None:
            family = F.family_of(choice)
            info = problem.bodies[step.obj]
            psi = choice.psi if choice.psi is not None else 0.0
            hand = problem.hand.opening if problem.hand is not None else None
            entry.update(family=family.name, faces=faces(info, psi),
                         width=float(F.closing_width(info, psi)),
                         pitch=float(t) if family.has_param and t is not None else None,
                         hand_opening=None if hand is None else float(hand))
        out.append(entry)
    return tuple(out)


def grasp_words(entry: dict) -> str:
    """One line for the terminal: `(pick a t): top, fingers on a's ±y faces (5.0 cm
    apart), hand opened 6.2 cm`."""
    head = f"{entry['action']}: {entry.get('family', '?')}"
    if entry.get("family") == "suction":
        angle = entry.get("contact_angle")
        return head + ("" if angle is None else f", contact angle {math.degrees(angle):.0f} deg")
    words = [head, f"fingers on {entry['object']}'s {entry['faces']} faces "
                   f"({100 * entry['width']:.1f} cm apart)"]
    if entry.get("pitch") is not None:
        words.append(f"pitched down {math.degrees(entry['pitch']):.0f} deg")
    if entry.get("hand_opening") is not None:
        words.append(f"hand opened {100 * entry['hand_opening']:.1f} cm")
    return ", ".join(words)
