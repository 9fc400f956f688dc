"""How each grasp of an answer holds its object, in terms a user can check
against the scene: the family, the pair of faces the fingers close on, the
width between them, a side grasp's pitch and the hand's opening; for the
planar robot, the contact angle of its suction; and how each push touches its
object (the face, the pusher, the offset). Written to solution.json's `grasps`
and printed by `solve` (docs/formats.md, "solution.json")."""

from __future__ import annotations

import math

from tampcli.optimize import grasp_families as F
from tampcli.optimize.kinds.push_contact import finger_shift


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
        choice = choices.get(step.index)
        t = keyframes.grip.get(step.index)
        if getattr(step.kind, "within_cone", False) and choice is not None:
            out.append(push_entry(problem, step, choice, t))
            continue
        if step.kind.fingers is not True:
            continue
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


# A box's face by the angle of its inward normal in the object's frame (push_contact),
# in quarter turns: 0 pushes the -x face (towards +x).
_BOX_FACES = {0: "-x", 1: "-y", 2: "+x", 3: "+y"}


def push_entry(problem, step, choice, t) -> dict:
    """How a push touches its object (its family: the kind's name): the face (a box's
    `-x`, `+y`, ...: the face pushed, the object moving away from it; a cylinder's
    direction of push in its own frame, degrees), the pusher (`rim` for the planar
    disk; an arm's hand `down`, the open fingers' side on the face, or `level`, its
    fingertips on it), for an arm which `fingers` touch (`both`, or `one` alone on a
    face narrower than their spread) and the contact's offset from the face's middle
    along it (m)."""
    angle = choice.face if choice.face is not None else 0.0
    if problem.bodies[step.obj].disk:
        face = f"{math.degrees(angle):.0f} deg"
    else:
        face = _BOX_FACES[round(angle / (0.5 * math.pi)) % 4]
    pusher = "rim" if problem.planar else ("level" if choice.level else "down")
    entry = {"action": step.name, "object": step.obj, "family": step.kind.name, "face": face,
             "pusher": pusher, "offset": None if t is None else float(t)}
    if not problem.planar:
        entry["fingers"] = "front" if choice.crosswise else ("one" if choice.finger else "both")
    if choice.finger and not problem.planar and t is not None:
        # One finger: the hand's axis stands beside the contact, along the face (the
        # tool's y is the face's tangent: push_contact.arm_face_grip, level_face_grip).
        shift = choice.shift if choice.shift is not None else finger_shift(
            choice.finger, problem.world.finger_span)
        entry["axis_offset"] = float(t - shift)
        entry["axis_side"] = _side(problem.bodies[step.obj], angle + 0.5 * math.pi
                                   if t - shift >= 0 else angle - 0.5 * math.pi)
    return entry


def _side(info, angle: float) -> str:
    """A direction in the object's frame in words: a box's axis (`+y`), else degrees."""
    if info.disk:
        return f"{math.degrees(angle) % 360:.0f} deg"
    return {0: "+x", 1: "+y", 2: "-x", 3: "-y"}[round(angle / (0.5 * math.pi)) % 4]


def grasp_words(entry: dict) -> str:
    """One line for the terminal: `(pick a t): top, fingers on a's ±y faces (5.0 cm
    apart), hand opened 6.2 cm`; `(push c x y): the hand down, its fingers' side on c's
    -x face, 0.4 cm off its middle`."""
    head = f"{entry['action']}: {entry.get('family', '?')}"
    if "pusher" in entry:
        one = entry.get("fingers") == "one"
        down = {"one": "one finger's side", "front": "its front finger's side (the other "
                "behind it)"}.get(entry.get("fingers"), "its fingers' side")
        pusher = {"rim": "the disk's rim",
                  "down": "the hand down, " + down,
                  "level": "the hand level, " + ("one fingertip" if one
                                                 else "its fingertips")
                  }.get(entry.get("pusher"), "?")
        words = f"{entry['action']}: {pusher} on {entry['object']}'s {entry.get('face')} face"
        offset = entry.get("offset")
        words += "" if offset is None else f", {100 * offset:.1f} cm off its middle"
        if entry.get("axis_offset") is not None:
            words += (f", the hand's axis beside it, {100 * abs(entry['axis_offset']):.1f} cm "
                      f"off the face's middle towards {entry['object']}'s "
                      f"{entry['axis_side']}")
        return words
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
