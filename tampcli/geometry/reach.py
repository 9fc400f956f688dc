"""A ball the arm's tool cannot leave: proofs that a pose is out of reach rest on it.

The ball is centred on the first joint's origin, or the second's where it lies on
the first joint's axis (it turns in place). A link's frame origin does not move
with its own joint, so the tool's distance from the centre is at most the summed
lengths of the offsets between consecutive joint origins whatever the joint
values (the triangle inequality), taken as tight as the chain allows: offsets a
joint turns about their own line stay one straight segment with the next; a
segment the next one continues along the closing joint's axis is one length
(the Panda's wrist, flange and hand: 0.228 m, not 0.298). Measured against the
farthest tool of 20000 random configurations within the joint limits: Panda
0.9489 m (0.9485 sampled), KUKA iiwa 1.0360 (1.0359), xArm6 0.9010 (0.9009). A
prismatic joint on the way, the first one included, leaves no bound (None).
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.geometry.chain import PRISMATIC, REVOLUTE

_PARALLEL = 1e-9  # |v x a| below this (m): v lies along the axis a


def _along(v: np.ndarray, axis: np.ndarray) -> bool:
    return float(np.linalg.norm(np.cross(v, axis))) < _PARALLEL


def reach_ball(world) -> tuple[np.ndarray, float] | None:
    """(centre, radius) in the world, or None (the planar robot; a prismatic joint)."""
    if world.scene.robot.model == "planar":
        return None
    chain = world.chain
    frames = chain.fk_list(world.start)
    joints = [i for i, link in enumerate(chain.links) if link.q_index >= 0]
    if not joints:
        return None
    centre_link = joints[0]
    if chain.links[centre_link].joint_type != REVOLUTE:
        # A prismatic first joint (a track) carries every later origin along with it:
        # no ball about the start's (blind28 p06: a 1.12 m ball about the carriage's
        # start position 'proved' a part 0.35 m from the shoulder out of reach).
        return None
    if len(joints) > 1:
        first, second = frames[joints[0]], frames[joints[1]]
        axis = first[:3, :3] @ chain.links[joints[0]].axis
        off = second[:3, 3] - first[:3, 3]
        if np.linalg.norm(off - (off @ axis) * axis) < 1e-6:
            centre_link = joints[1]
    path, i = [], chain.index[world.tool_link]
    while i > centre_link:
        path.append(chain.links[i])
        i = chain.links[i].parent
    if i != centre_link:
        return None
    radius = _chain_length(path[::-1])
    return None if radius is None else (frames[centre_link][:3, 3].copy(), radius)


def _chain_length(links) -> float | None:
    """The bound on the tool's distance from the first link's origin along `links`."""
    total = 0.0
    v = np.zeros(3)  # the open segment, in the current link's coordinates
    back = np.eye(3)  # current coordinates -> the last closing joint's (while rigid)
    rigid = True  # no joint turned since that joint: `back` is fixed
    closed = None  # (segment, axis) the last revolute joint closed, in its coordinates
    for link in links:
        moving = link.q_index >= 0 and link.joint_type == REVOLUTE
        if link.q_index >= 0 and link.joint_type == PRISMATIC:
            return None
        v = link.origin[:3, :3].T @ (v + link.origin[:3, 3])
        back = back @ link.origin[:3, :3]
        if not moving:
            continue
        if _along(v, link.axis):
            rigid = False  # it turns about its own line: one segment still
            continue
        if closed is not None:
            total += float(np.linalg.norm(closed[0]))
        closed, v, back, rigid = (v, link.axis), np.zeros(3), np.eye(3), True
    if closed is None:
        return total + float(np.linalg.norm(v))
    prev, axis = closed
    v = back @ v
    if rigid and _along(v, axis):  # the last segment runs along the closing joint's axis
        a, b = float(prev @ axis), float(v @ axis)
        return total + math.sqrt(max(0.0, prev @ prev + 2 * a * b + b * b))
    return total + float(np.linalg.norm(prev)) + float(np.linalg.norm(v))
