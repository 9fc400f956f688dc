"""What `tampcli check` says about a problem's geometry: `scene_summary`.

Loading refuses a bad scene (a SceneError, exit 2). A good one is
summarized: robot and joint limits, bodies, regions, modes, the robot's
support and self-collision pairs, the closest pairs of the start state, and
warnings (goal regions the robot cannot reach, actions without a mode).
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.locate import find_scene
from tampcli.geometry.reach import reach_ball
from tampcli.geometry.scene import read_scene
from tampcli.geometry.startcheck import check_start_state
from tampcli.geometry.world import World
from tampcli.pddl import ast

REPORT_DISTANCE = 0.05  # m: start-state pairs closer than this are listed


def scene_summary(domain: ast.Domain, problem: ast.Problem, problem_path, scene_path=None,
                  modes=None) -> dict | None:
    """A JSON-ready summary of the scene of `problem`, or None when it has none.

    `modes`: the domain's Modes (optimize.modes), loaded by the caller.
    Raises SceneError (located) when the scene file is bad.
    """
    scene_path = scene_path or find_scene(problem_path)
    if scene_path is None:
        return None
    scene, src = read_scene(scene_path, domain, problem, modes=modes)
    warnings: list[str] = []
    with World(scene, visuals=False) as world:
        checker = CollisionChecker(world)
        check_start_state(world, checker, src)
        contacts = start_pairs(world, checker, REPORT_DISTANCE)
        warnings += _reach_warnings(world, scene, _goal_names(problem.goal))
        warnings += _floating_warnings(world, scene)
        robot = {
            "model": scene.robot.model,
            # The whole pose, as a body's: a turned base turns the arm and its reach.
            "base": _round(scene.robot.base),
            "tool_link": world.tool_link,
            "joints": list(world.joint_names),
            "lower": _round(world.lower),
            "upper": _round(world.upper),
            "start": _round(world.start),
        }
        if scene.robot.model != "planar" and world.gripper_opening is not None:
            # The two figures robots.md checks a new arm's tool frame by (m).
            robot["gripper_opening"] = round(float(world.gripper_opening), 4)
            robot["fingertip_depth"] = round(float(world.fingertip_depth or 0.0), 4)
        support = sorted(checker.support)
        # Pairs of link parts: a link with several convex parts would repeat a name pair.
        self_pairs = [list(pair) for pair in dict.fromkeys(checker.self_pair_names)]
    if modes is None:
        warnings.append("no modes.toml beside the domain: every action is symbolic only")
    else:
        for name in modes.missing:
            warnings.append(f"action {name!r} has no table in {modes.path}: it is symbolic "
                            "only (mode \"none\")")
    return {
        "scene": str(scene_path),
        "modes": modes.path if modes is not None else None,
        "robot": robot,
        "support": support,
        "self_collision_pairs": self_pairs,
        "bodies": [_body(b) for b in scene.bodies],
        "regions": [{"name": r.name, "on": r.on, "center": list(r.center),
                     "size": list(r.size)} for r in scene.regions],
        "action_modes": {name: mode.kind for name, mode in (modes.items() if modes else ())},
        "start_contacts": [{"a": c.a, "b": c.b, "kind": pair_kind(c),
                            "distance": round(c.distance, 5)} for c in contacts],
        "start_contacts_within": REPORT_DISTANCE,
        "warnings": warnings,
    }


def start_pairs(world, checker, within: float) -> list:
    """Every pair of the start state closer than `within` (m), closest first: robot link
    and body, robot link and link (the self-collision pairs), and body and body (an
    object near a wall, on a table, beside another object). Two obstacles are left
    out, as the start check leaves them: one fixed solid is often built of parts."""
    pairs = list(checker.distances(world.start, activation=within, static=True))
    bodies = world.scene.bodies
    for i, a in enumerate(bodies):
        for b in bodies[i + 1:]:
            if a.fixed and b.fixed and a.obstacle and b.obstacle:
                continue
            c = checker.body_distance(a.name, a.matrix, b.name, b.matrix)
            if c.distance < within:
                pairs.append(c)
    return sorted(pairs, key=lambda c: c.distance)


def pair_kind(contact) -> str:
    """"robot-body", "robot-robot" or "body-body", from the parts' name prefixes."""
    sides = ["robot" if name.startswith(("link:", "held:")) else "body"
             for name in (contact.a, contact.b)]
    return "-".join(sorted(sides, key=lambda side: side != "robot"))


def _body(body) -> dict:
    """A body as `check --json` shows it: pose as [x, y, z, qx, qy, qz, qw]."""
    out = {"name": body.name, "shape": body.shape, "size": list(body.size),
           "pose": _round(body.pose), "fixed": body.fixed, "obstacle": body.obstacle}
    if body.shape in ("mesh", "urdf"):
        out["file"] = body.mesh or body.urdf
        out["scale"] = list(body.scale)
    if getattr(body, "mass", None) is not None:
        out["mass"] = float(body.mass)  # kg, as the scene gives it
    return out


def _round(values, digits: int = 6) -> list[float]:
    return [round(float(v), digits) for v in values]


def _goal_names(formula) -> set[str]:
    """All object names in the atoms of a goal formula."""
    names: set[str] = set()
    stack = [formula]
    while stack:
        f = stack.pop()
        if isinstance(f, ast.Atom):
            names.update(a for a in f.args if not a.startswith("?"))
        elif isinstance(f, ast.Not):
            stack.append(f.part)
        elif isinstance(f, ast.And | ast.Or):
            stack.extend(f.parts)
        elif isinstance(f, ast.Imply):
            stack.extend((f.antecedent, f.consequent))
        elif isinstance(f, ast.Exists | ast.Forall):
            stack.append(f.body)
    return names


def _reach_warnings(world, scene, goal_names: set[str]) -> list[str]:
    out = []
    for region in scene.regions:
        if region.name not in goal_names:
            continue
        support = scene.body(region.on)
        top = support.matrix[2, 3] + _half_height(support)
        lo, hi = region.lower, region.upper
        if scene.robot.model == "planar":
            inside = np.all(hi >= world.lower) and np.all(lo <= world.upper)
            if not inside:
                out.append(f"goal region {region.name!r} lies outside the planar robot's "
                           f"workspace x, y in [{world.lower[0]:.2f}, {world.upper[0]:.2f}] x "
                           f"[{world.lower[1]:.2f}, {world.upper[1]:.2f}]")
            continue
        shoulder, reach = _shoulder_and_reach(world)
        nearest = np.array([np.clip(shoulder[0], lo[0], hi[0]),
                            np.clip(shoulder[1], lo[1], hi[1]), top])
        gap = float(np.linalg.norm(nearest - shoulder))
        if gap > reach:
            out.append(f"goal region {region.name!r} is {gap:.2f} m from the robot's shoulder, "
                       f"beyond its reach of about {reach:.2f} m")
    if scene.robot.model == "planar":
        return out
    shoulder, reach = _shoulder_and_reach(world)
    for body in scene.bodies:
        if body.fixed:
            continue
        gap = float(np.linalg.norm(body.matrix[:3, 3] - shoulder))
        if gap > reach + _half_diagonal(body):
            out.append(f"object {body.name!r} stands {gap:.2f} m from the robot's shoulder, "
                       f"beyond its reach of {reach:.2f} m: it cannot be picked where it "
                       f"stands (a proof: `solve` drops those picks before any skeleton)")
    return out


def _half_diagonal(body) -> float:
    """The radius of a body's bounding sphere about its origin (a generous one for a
    mesh or URDF body: nothing is proved of those here)."""
    if body.shape == "box":
        return 0.5 * float(np.linalg.norm(body.size))
    if body.shape == "cylinder":
        return float(np.hypot(body.size[0], body.size[1] / 2))
    if body.shape == "sphere":
        return float(body.size[0])
    return math.inf


FLOATING = 0.005  # m: a movable object's bottom this far over what is under it floats


def _floating_warnings(world, scene) -> list[str]:
    """Movable upright boxes, cylinders and spheres whose bottom stands more than
    FLOATING over the top of every body under their centre (blind38 DOC_GAPS 1: a puck
    2 cm over a bench passed `check` silently, while a sunk one is refused; `solve`
    then read it as `the planar robot cannot lift p2 onto bench`, a proof)."""
    out = []
    boxes = {b.name: world.aabb(b.name) for b in scene.bodies}
    for body in scene.bodies:
        if body.fixed or not _plain_upright(body):
            continue
        bottom = body.matrix[2, 3] - _half_height(body)
        x, y = body.matrix[:2, 3]
        below = []
        for other in scene.bodies:
            if other.name == body.name:
                continue
            lo, hi = boxes[other.name]
            if not (lo[0] <= x <= hi[0] and lo[1] <= y <= hi[1]):
                continue
            top = other.matrix[2, 3] + _half_height(other) if _plain_upright(other) \
                else float(hi[2])
            if top <= bottom + FLOATING:
                below.append((top, other.name))
        if not below:
            out.append(f"nothing is under {body.name!r}'s centre: it floats (solve does not "
                       "let objects fall; a place sets them on a support)")
            continue
        top, name = max(below)
        if bottom - top > FLOATING:
            out.append(f"{body.name!r} floats {100 * (bottom - top):.1f} cm over {name!r} "
                       f"(its bottom at z = {bottom:.3f}, the top of {name!r} at z = {top:.3f}): "
                       f"did you mean pose z = {top + _half_height(body):.3f}?")
    return out


def _plain_upright(body) -> bool:
    return body.shape in ("box", "cylinder", "sphere") and bool(body.matrix[2, 2] > 1 - 1e-6)


def _half_height(body) -> float:
    if body.shape == "box":
        return body.size[2] / 2
    if body.shape == "cylinder":
        return body.size[1] / 2
    if body.shape == "sphere":
        return body.size[0]
    return 0.0


def _shoulder_and_reach(world) -> tuple[np.ndarray, float]:
    """The arm's reach ball (geometry/reach.py: a bound); infinite without one."""
    ball = reach_ball(world)
    return ball if ball is not None else (world.scene.robot.base_pose[:3, 3], math.inf)

