"""`check`'s warnings on a scene's summary (geometry/report.py's dict) that the
geometry report itself cannot give: they need the optimizer's rules (its margins, the
grasp families' figures). Not errors: `check` still exits 0."""

from __future__ import annotations

from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.units import cm


def scene_warnings(scene: dict) -> list[str]:
    """Every warning below, in order."""
    return _near_start(scene) + _ungraspable(scene)


def _near_start(scene: dict) -> list[str]:
    """The robot's parts closer than solve's margin to a body at the start: not an
    error (the first motion keeps half that distance), but a slot the author may not
    have meant (a palm 1.3 mm from a partition)."""
    margin = OptimizeOptions().margin
    def bare(part: str) -> str:
        return part.partition(":")[2] or part

    return [f"the robot starts {1000 * c['distance']:.1f} mm from {bare(c['b'])} "
            f"({bare(c['a'])}): "
            f"closer than solve's {1000 * margin:.0f} mm margin, which its first motion "
            "then keeps at half that distance"
            for c in scene.get("start_contacts", [])
            if c.get("kind") == "robot-body" and c["distance"] < margin]


def _ungraspable(scene: dict) -> list[str]:
    """Movable boxes, cylinders and spheres no grasp of the arm can take, where a mode
    grasps: too wide for its opening, or lower than its top grasp takes (its open
    fingertips' reach plus grasp_families.MIN_DEPTH and the tight margin,
    docs/formats.md, "Grasp") and than a side grasp's SIDE_MIN_HEIGHT. Only a push can
    move such an object; a goal that needs it lifted fails at every skeleton."""
    from tampcli.optimize import grasp_families as F
    from tampcli.optimize.kinds import KINDS

    robot = scene["robot"]
    opening, depth = robot.get("gripper_opening"), robot.get("fingertip_depth")
    grasps = any(k in KINDS and KINDS[k].fingers is True
                 for k in scene.get("action_modes", {}).values())
    if opening is None or not grasps:
        return []
    least = depth + F.MIN_DEPTH + OptimizeOptions().tight_margin
    pushes = any(k in KINDS and KINDS[k].within_cone
                 for k in scene.get("action_modes", {}).values())
    # blind38 DOC_GAPS 5: "only a push can move it" where the domain has no push.
    only = "only a push can move it" if pushes else "no action of the domain can move it"
    out = []
    for body in scene["bodies"]:
        size, shape = body["size"], body["shape"]
        if body["fixed"] or shape not in ("box", "cylinder", "sphere"):
            continue
        across = min(size[:2]) if shape == "box" else 2 * size[0]
        tall = {"box": size[-1], "cylinder": size[-1], "sphere": 2 * size[0]}[shape]
        name, model = body["name"], robot["model"]
        if not F.fits(across, opening):
            out.append(f"{name} is {100 * across:.1f} cm across at its narrowest: wider than "
                       f"the {model}'s gripper takes ({cm(opening - F.GRIPPER_SLACK)} cm); "
                       f"{only}")
        elif tall < least and tall < F.SIDE_MIN_HEIGHT:
            out.append(f"{name} is {100 * tall:.1f} cm tall: lower than any grasp of the "
                       f"{model} takes (from the top {100 * least:.2f} cm and up, its "
                       f"fingertips reaching {100 * depth:.1f} cm beyond the tool origin; "
                       f"from the side {100 * F.SIDE_MIN_HEIGHT:.0f} cm); {only}")
    return out
