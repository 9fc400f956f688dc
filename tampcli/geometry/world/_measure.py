"""What is loaded in a PyBullet client, read into numpy: the robot's kinematic
tree (a Chain), collision shapes, axis-aligned boxes.

Every function here is a query: what it moves for a measurement it puts back.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.chain import FIXED, PRISMATIC, REVOLUTE, Chain, ChainLink
from tampcli.geometry.shapes import Shape, mesh_hulls, primitive

# PyBullet's collision geometry types (getCollisionShapeData()[2]).
GEOM_SPHERE, GEOM_BOX, GEOM_CYLINDER, GEOM_MESH, GEOM_CAPSULE = 2, 3, 4, 5, 7


def measure_chain(pb, client: int, body: int, variables: dict[str, int],
                  fixed_values: dict[int, float], link_names: dict[int, str] | None = None,
                  ) -> Chain:
    """Build the Chain of a PyBullet body.

    `variables` maps joint name -> index in q; `fixed_values` gives the value
    of other movable joints (fingers). The simulator state is restored.

    The joint origins and axes are measured by moving the joints, not read
    from the joint info: PyBullet moves origins into inertial frames, so
    reading them directly would need that bookkeeping.
    """
    n_joints = pb.getNumJoints(body, physicsClientId=client)
    infos = [pb.getJointInfo(body, j, physicsClientId=client) for j in range(n_joints)]
    saved = [pb.getJointState(body, j, physicsClientId=client)[0] for j in range(n_joints)]
    movable = [j for j in range(n_joints) if infos[j][2] in (REVOLUTE, PRISMATIC)]

    def frames_at(values: dict[int, float]):
        for j in movable:
            pb.resetJointState(body, j, values.get(j, 0.0), physicsClientId=client)
        out = {-1: _base_frame(pb, client, body)}
        for j in range(n_joints):
            state = pb.getLinkState(body, j, computeForwardKinematics=True,
                                    physicsClientId=client)
            out[j] = transforms.pose(transforms.quat_to_matrix(state[5]), state[4])
        return out

    try:
        zero = frames_at({})
        base_name = pb.getBodyInfo(body, physicsClientId=client)[0].decode()
        names = dict(link_names or {})
        links = [ChainLink(names.get(-1, base_name), -1, np.eye(4), FIXED, np.zeros(3), -1,
                           0.0, -1)]
        pb_to_chain = {-1: 0}
        for j in range(n_joints):
            info = infos[j]
            parent_pb = info[16]
            origin = _clean(transforms.pose_inverse(zero[parent_pb]) @ zero[j])
            joint_name = info[1].decode()
            kind = info[2] if info[2] in (REVOLUTE, PRISMATIC) else FIXED
            axis = np.zeros(3)
            if kind != FIXED:
                moved = frames_at({j: 0.5})[j]
                rel = transforms.pose_inverse(zero[j]) @ moved
                if kind == REVOLUTE:
                    axis = transforms.rotation_log(rel[:3, :3]) / 0.5
                else:
                    axis = rel[:3, 3] / 0.5
                axis = _snap(axis / np.linalg.norm(axis))
            links.append(ChainLink(names.get(j, info[12].decode()), pb_to_chain[parent_pb],
                                   origin, kind, axis, variables.get(joint_name, -1),
                                   fixed_values.get(j, 0.0), j))
            pb_to_chain[j] = len(links) - 1
    finally:
        for j in movable:
            pb.resetJointState(body, j, saved[j], physicsClientId=client)
    return Chain(links, zero[-1], len(variables))


def _base_frame(pb, client: int, body: int) -> np.ndarray:
    """URDF frame of the base link (PyBullet reports its centre of mass)."""
    pos, orn = pb.getBasePositionAndOrientation(body, physicsClientId=client)
    inertial = pb.getDynamicsInfo(body, -1, physicsClientId=client)[3:5]
    com = transforms.pose(transforms.quat_to_matrix(orn), pos)
    local = transforms.pose(transforms.quat_to_matrix(inertial[1]), inertial[0])
    return com @ transforms.pose_inverse(local)


def _snap(v: np.ndarray, tol: float = 1e-6) -> np.ndarray:
    """Round values within tol of 0 or +-1: PyBullet reports float32-rounded frames."""
    out = np.array(v, dtype=float)
    for target in (0.0, 1.0, -1.0):
        out[np.abs(out - target) < tol] = target
    return out


def _clean(t: np.ndarray) -> np.ndarray:
    out = t.copy()
    out[:3, :3] = _snap(out[:3, :3])
    u, _, vt = np.linalg.svd(out[:3, :3])
    out[:3, :3] = _snap(u @ vt)
    out[:3, 3] = np.round(out[:3, 3], 7)
    return out


def link_shapes(pb, client: int, body: int, link: int) -> list[Shape]:
    """Collision shapes of one link of a PyBullet body, in its URDF link frame.

    PyBullet reports each shape relative to the link's inertial frame, and
    one entry per convex part of a mesh (all naming the same file): each
    file is read once.
    """
    inertial = pb.getDynamicsInfo(body, link, physicsClientId=client)[3:5]
    to_link = transforms.pose(transforms.quat_to_matrix(inertial[1]), inertial[0])
    shapes = []
    meshes_seen = set()
    for data in pb.getCollisionShapeData(body, link, physicsClientId=client):
        kind, dims, filename = data[2], data[3], data[4]
        local = to_link @ transforms.pose(transforms.quat_to_matrix(data[6]), data[5])
        if kind == GEOM_BOX:
            shapes.append(primitive("box", dims, local))
        elif kind == GEOM_SPHERE:
            shapes.append(primitive("sphere", dims[:1], local))
        elif kind == GEOM_CYLINDER:
            shapes.append(primitive("cylinder", (dims[1], dims[0]), local))
        elif kind == GEOM_CAPSULE:
            shapes.append(primitive("capsule", (dims[1], dims[0]), local))
        elif kind == GEOM_MESH:
            name = filename.decode() if isinstance(filename, bytes) else filename
            key = (name, tuple(dims), tuple(np.round(local, 9).ravel()))
            if name in ("", "unknown_file") or key in meshes_seen:
                continue
            meshes_seen.add(key)
            shapes.extend(mesh_hulls(name, dims, local))
    return shapes


def body_shapes(pb, client: int, body: int, base_pose: np.ndarray) -> list[Shape]:
    """Collision shapes of all links of a body, in the frame `base_pose` (4x4, world)."""
    base_inv = transforms.pose_inverse(base_pose)
    shapes = []
    for link in range(-1, pb.getNumJoints(body, physicsClientId=client)):
        if link == -1:
            frame = np.eye(4)
        else:
            state = pb.getLinkState(body, link, computeForwardKinematics=True,
                                    physicsClientId=client)
            frame = base_inv @ transforms.pose(transforms.quat_to_matrix(state[5]), state[4])
        for s in link_shapes(pb, client, body, link):
            shapes.append(dataclasses.replace(s, local=frame @ s.local,
                                              center=frame[:3, :3] @ s.center + frame[:3, 3]))
    return shapes


def aabb(pb, client: int, body: int, links=None) -> tuple[np.ndarray, np.ndarray]:
    """(lo, hi) of a box around the body's `links` (default: all) as it stands now."""
    if links is None:
        links = range(-1, pb.getNumJoints(body, physicsClientId=client))
    los, his = [], []
    for link in links:
        lo, hi = pb.getAABB(body, link, physicsClientId=client)
        los.append(lo)
        his.append(hi)
    return np.min(los, axis=0), np.max(his, axis=0)


def gripper_size(pb, client: int, body: int, fingers, chain, tool: int, q,
                 reach: float = 0.02, values: dict | None = None
                 ) -> tuple[float, float, tuple[float, float]] | None:
    """(opening, fingertip depth, span) of open fingers at configuration q, in the
    tool frame (chain link `tool`), from the exact support of their collision shapes
    (margins included: the solids PyBullet sees). `values`: chain link index -> its
    finger joint's value, for fingers not open.

    Opening: the gap along y between the finger parts on either side that
    come within `reach` of the tool origin's height (linkage bars higher up
    are not what closes on an object). Depth: how far they reach along z.
    Span: (inner, outer) distance along y from the tool's axis to those finger
    parts' near and far sides, the mean of the two sides: where a finger's
    side stands when the fingers, spread along a face, push it.
    """
    if fingers is None:
        return None
    if values:
        frames = chain.refixed(chain.fk_batch(np.asarray(q, dtype=float).reshape(1, -1)),
                               {i: np.array([v]) for i, v in values.items()})[0]
    else:
        frames = chain.fk_list(q)
    to_tool = transforms.pose_inverse(frames[tool])
    by_pb = {link.pb_index: i for i, link in enumerate(chain.links)}
    depth = -np.inf
    inner, outer = [np.inf, np.inf], [0.0, 0.0]  # the +y side's, the -y side's
    y, z = np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0])
    for link in fingers.links:
        for shape in link_shapes(pb, client, body, link):
            f = to_tool @ frames[by_pb[link]] @ shape.local
            rot, at = f[:3, :3], f[:3, 3]

            def extent(d, rot=rot, at=at, shape=shape):  # d: a unit vector
                return shape.support(rot.T @ d) + float(d @ at) + shape.margin

            top = extent(z)
            depth = max(depth, top)
            if top < -reach:
                continue
            low_y, high_y = -extent(-y), extent(y)
            for side, near, far in ((0, low_y, high_y), (1, -high_y, -low_y)):
                if near > 0:
                    inner[side] = min(inner[side], near)
                    outer[side] = max(outer[side], far)
    if not np.isfinite(depth):
        return None
    closed = not all(np.isfinite(inner))
    opening = 0.0 if closed else inner[0] + inner[1]
    span = (0.0, float(max(outer))) if closed else (0.5 * opening, 0.5 * (outer[0] + outer[1]))
    return float(opening), float(depth), span
