"""Geometric checks of a scene's start state: overlaps, joint limits, collisions.

Resting contact is not overlap: bodies may interpenetrate by up to
OVERLAP_TOLERANCE (a few mm of modelling slack), and the robot's base may
touch the body it stands on.

Deliberately not checked: two obstacles (fixed bodies the PDDL problem does
not name). A fixed scene is often built from touching or overlapping parts
(a table top and its legs, a shelf and its boards); they never move, so no
query of the planner depends on their overlap. A movable body, and a fixed
body the problem names (a surface things are placed on), are checked
against every other body. See docs/scene.md.
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.errors import SceneError, source_line_at

OVERLAP_TOLERANCE = 0.003  # m
LIMIT_TOLERANCE = 1e-6  # rad or m


def start_problems(world, checker) -> list[tuple[str, str, str]]:
    """(key, subject, message) for each problem of the start state; empty when fine."""
    problems = []
    scene = world.scene
    bodies = scene.bodies
    for i, a in enumerate(bodies):
        for b in bodies[i + 1:]:
            if a.fixed and b.fixed and a.obstacle and b.obstacle:
                continue  # one solid built from parts (see the module docstring)
            c = checker.body_distance(a.name, a.matrix, b.name, b.matrix)
            if c.distance < -OVERLAP_TOLERANCE:
                problems.append(("objects.pose", b.name, f"{b.name!r} overlaps {a.name!r} by "
                                 f"{-c.distance * 1000:.1f} mm in the start state"
                                 + _resting_hint(world, a, b)))
    problems += _movable_frames(world)
    q = world.start
    for name, v, lo, hi in zip(world.joint_names, q, world.lower, world.upper, strict=True):
        if v < lo - LIMIT_TOLERANCE or v > hi + LIMIT_TOLERANCE:
            problems.append(("robot.start", "", f"joint {name} = {v:.4g} is outside its limits "
                             f"[{lo:.4g}, {hi:.4g}]"))
    for c in checker.distances(q, activation=0.0, static=True):
        if c.distance < -OVERLAP_TOLERANCE:
            problems.append(("robot.start", "", f"the start configuration is in collision: "
                             f"{c.a} and {c.b} overlap by {-c.distance * 1000:.1f} mm"))
    return problems


def _resting_hint(world, below, body) -> str:
    """What z would put `body` on `below`, where it sinks into its top."""
    lo_b, hi_b = world.aabb(below.name)
    lo, hi = world.aabb(body.name)
    z = body.matrix[2, 3]
    if not lo[2] < hi_b[2] < hi[2] or z <= 0.5 * (lo_b[2] + hi_b[2]):
        return ""
    return f" (expected it resting on {below.name!r}: pose z = {z + hi_b[2] - lo[2]:.4g})"


MESH_CENTRE = 0.001  # m: a movable mesh's box centre this near its origin counts as on it


def _movable_frames(world) -> list[tuple[str, str, str]]:
    """A movable mesh or URDF is planned as its bounding box, centred on its origin and
    aligned with the world's axes at the start: one turned about z would be gripped
    as its wider world-aligned box (blind7 p05: a prism 6.9 cm across refused as
    9.2 cm wide, a false proof), one whose origin is off its box's centre would be
    moved by the wrong point."""
    out = []
    for body in world.scene.bodies:
        if body.fixed or body.shape not in ("mesh", "urdf"):
            continue
        m = body.matrix
        turn = math.degrees(math.atan2(m[1, 0], m[0, 0]))
        if abs(turn) > 1e-4:
            out.append(("objects.pose", body.name, f"a movable {body.shape} must start "
                        f"unturned (its pose's yaw 0: the planner takes it as its "
                        f"world-aligned bounding box): {body.name!r} is turned {turn:.1f} deg; "
                        "turn it in its file instead"))
            continue
        lo, hi = world.aabb(body.name)
        off = 0.5 * (lo + hi) - m[:3, 3]
        if float(np.linalg.norm(off)) > MESH_CENTRE:
            out.append(("objects.pose", body.name, f"a movable {body.shape}'s origin must be "
                        f"the centre of its bounding box (the planner moves it by that "
                        f"point): {body.name!r}'s box centre lies "
                        f"({off[0]:.4f}, {off[1]:.4f}, {off[2]:.4f}) m from it"))
    return out


def check_start_state(world, checker, src=None) -> None:
    """Raise a located SceneError for the first problem of the start state of
    `world.scene`; `src` (the scene's TomlSource) places it on the key's line."""
    problems = start_problems(world, checker)
    if problems:
        raise located_error(world.scene, src, *problems[0])


def located_error(scene, src, key: str, subject: str, message: str) -> SceneError:
    if key == "objects.pose":
        index = next(i for i, b in enumerate(scene.bodies) if b.name == subject)
        line = src.line("objects", index, "pose") if src else scene.bodies[index].line
    elif src is not None:
        # The planar robot starts at its base unless `start` is given.
        given = ("robot", 0, "start") in src.lines
        line = src.line("robot", 0, "start" if given else "base")
    else:
        line = scene.robot.line
    text = src.text if src is not None else None
    return SceneError(message, path=scene.path, line=line, key=key,
                      source_line=source_line_at(text, line) if text else None)
