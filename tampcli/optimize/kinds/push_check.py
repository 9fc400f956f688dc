"""What `verify` re-measures of a push (kinds/push.py's `check`): a push, not a drag.

From the trajectory alone: the face touched is the one the robot's touch (its
nearest points' middle) is beyond at the start of the pushing motion
(push_contact.contacted_face); the pusher
touches it (within the touch tolerance) without going into the object, also
on the last segment of its approach (which the collision check leaves to the
mode); every step of the object moves into that face within the friction
cone; a box keeps its yaw (within TURN), and every object its height, upright.
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize.kinds.push_contact import PUSH_FRICTION, contacted_face

PENETRATION = 1e-3  # m: deeper than this into the object is more than touching
SLACK = 1e-3  # of a step's length: rounding in the cone test
STILL = 1e-6  # m: shorter steps have no direction
# rad: a box turns with the hand at most this much between the keyframes (which hold
# its yaw exactly): the arm's two fingers touch the face along a line and can carry the
# moment of such a turn; the planar disk cannot turn at all. A cylinder or sphere
# (BodyInfo.disk) may turn: its footprint is the same at any yaw, and only where its
# centre goes is held to the push rule.
TURN = math.radians(2.0)
LIFT = 1e-3  # m and 1 - cos(tilt): the pushed object keeps its height and stays upright
APPROACH_SAMPLES = 10  # points on the approach's last segment
TOUCH_BAND = 2e-3  # m: links this much farther than the nearest touch the object too


def check_push(walk, step, touch: float) -> list[str]:
    """Violations of the push rule in words (walk: verify.StepCheck)."""
    problem, obj, name = walk.problem, step.obj, step.name
    info = problem.bodies[obj]
    start, end = walk.phase.start, walk.phase.end
    before = walk.before(obj)
    tools = problem.world.tool_poses(walk.traj[start:end + 1])
    grasp = transforms.pose_inverse(tools[0]) @ before
    objs = tools @ grasp
    gap, point = touch_at(problem, obj, before, walk.traj[start])
    # The face the pusher is beyond where it touches (one finger alone pushes a narrow
    # face: the tool's origin stands beside the object, not behind it).
    rel = transforms.pose_inverse(before) @ np.append(
        tools[0][:3, 3] if point is None else point, 1.0)
    face = contacted_face(info, rel[:3])
    out = []
    if gap > touch:
        out.append(f"{name}: the push starts {100 * gap:.1f} cm away from {obj}")
    if start > 0:
        s = np.linspace(0.0, 1.0, APPROACH_SAMPLES + 1)[:, None]
        qs = (1 - s) * walk.traj[start - 1] + s * walk.traj[start]
        gap = min(gap, clearance(problem, obj, before, qs))
    if gap < -PENETRATION:
        out.append(f"{name}: the pusher is {1000 * -gap:.1f} mm inside {obj}")
    n = before[:3, :3] @ face.normal
    e = before[:3, :3] @ face.tangent
    for i in range(len(objs) - 1):
        d = objs[i + 1][:3, 3] - objs[i][:3, 3]
        d[2] = 0.0
        length = float(np.linalg.norm(d))
        if length > STILL and abs(d @ e) > PUSH_FRICTION * (d @ n) + SLACK * length:
            off = math.degrees(math.atan2(abs(d @ e), d @ n))
            out.append(f"{name}: a step of {100 * length:.1f} cm at waypoint {start + i} is "
                       f"{off:.0f} deg off the normal of {obj}'s pushed face (a drag: the "
                       f"friction cone is {math.degrees(math.atan(PUSH_FRICTION)):.1f} deg)")
            break
    for i, pose in enumerate(objs):
        turn = math.atan2(before[0, 0] * pose[1, 0] - before[1, 0] * pose[0, 0],
                          before[0, 0] * pose[0, 0] + before[1, 0] * pose[1, 0])
        if abs(turn) > TURN and not info.disk:
            out.append(f"{name}: {obj} turns {math.degrees(turn):.1f} deg by waypoint "
                       f"{start + i}")
            break
        if abs(pose[2, 3] - before[2, 3]) > LIFT or pose[2, 2] < 1 - LIFT:
            out.append(f"{name}: {obj} lifts or tips at waypoint {start + i}")
            break
    return out


HORIZON = 0.05  # m: farther than this from the robot counts as this far


def _contacts(problem, obj: str, pose, qs) -> list[list]:
    """Per row of qs, the robot's contacts with `obj` (at `pose`) within HORIZON."""
    qs = np.atleast_2d(qs)
    others = frozenset(n for n in problem.bodies if n != obj)
    found = problem.checker.distances_many(qs, {obj: pose}, None, [others] * len(qs), HORIZON)
    target = f"body:{obj}"
    return [[c for c in contacts if target in (c.a, c.b)] for contacts in found]


def touch_at(problem, obj: str, pose, q):
    """(clearance, where the robot touches `obj`) at q: the middle of the robot's
    points nearest it, over the links within TOUCH_BAND of the nearest (world; None
    beyond HORIZON). Two fingers straddling a drum touch it either side: their middle
    is behind it."""
    (near,) = _contacts(problem, obj, pose, q)
    if not near:
        return HORIZON, None
    gap = min(c.distance for c in near)
    target = f"body:{obj}"
    points = [c.point_b if c.a == target else c.point_a for c in near
              if c.distance <= gap + TOUCH_BAND]
    return gap, np.mean(points, axis=0)


def clearance(problem, obj: str, pose, qs) -> float:
    """Smallest signed distance between the robot and `obj` (at `pose`) over the rows
    of qs (at most HORIZON: farther counts as that)."""
    return min((c.distance for near in _contacts(problem, obj, pose, qs) for c in near),
               default=HORIZON)
