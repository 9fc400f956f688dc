"""Signed distances, witness points, normals and joint gradients (python-fcl).

Pairs covered by `CollisionChecker.distances`:

- robot link vs scene body (every body except the held one and `ignore`);
- held object vs scene body, and held object vs robot links outside the
  tool's rigid group (the hand and fingers touch what they hold);
- robot self-collision between links of rigid groups that are not adjacent
  (adjacent = one joint apart), except pairs closer than SELF_MARGIN in the
  robot's default configuration (the Panda's "ready" pose, otherwise the
  middle of the joint limits): those touch by construction of the meshes.
  For the Panda that leaves 39 pairs (`self_pair_names`).
- Not covered: the robot's base group against the body it stands on (its
  support: a fixed body whose top face is at the base height, within 5 mm,
  under the base; for the planar robot, the whole robot against the floor
  it slides on), and pairs whose distance q cannot change (base-group links
  vs fixed bodies) unless `static=True`.

Broad phase: bounding spheres, then a certified lower bound (the gap of the
two solids' projections on the line between their centres); a pair goes to
FCL only when both are within `activation`. Distances are signed (negative
= penetration depth). `normal` points from a to b; `gradient` = d distance
/ d q = -normal . J_a(point_a) (+ normal . J_b(point_b) when b moves with q).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import fcl
import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.narrow import Placed, overlap, signed_distance
from tampcli.geometry.parts import (
    Part,
    body_shapes,
    fcl_object,
    find_support,
    rigid_groups,
    robot_parts,
)
from tampcli.geometry.scene import PANDA_READY

SELF_MARGIN = 0.01  # m: link pairs this close in the default configuration are not checked


@dataclass(frozen=True)
class Contact:
    a: str  # "link:NAME", "held:NAME" or "body:NAME"
    b: str
    distance: float  # signed, m; negative = penetration
    point_a: np.ndarray = field(repr=False)  # world witness point on a
    point_b: np.ndarray = field(repr=False)
    normal: np.ndarray = field(repr=False)  # unit, from a to b
    gradient: np.ndarray = field(repr=False)  # (n,) d distance / d q


class _Query:
    """Per-query state: link frames, joint axes and placed shapes, each computed once."""

    __slots__ = ("frames", "chain", "_axes", "_placed")

    def __init__(self, chain, q):
        self.chain = chain
        self.frames = chain.fk_list(q)
        self._axes = None
        self._placed: dict = {}

    def placed(self, key, part: Part, pose: np.ndarray | None) -> Placed:
        found = self._placed.get(key)
        if found is None:
            if pose is None:
                pose = self.frames[part.link]
            t = pose if part.identity_local else pose @ part.shape.local
            found = Placed(part.shape, t)
            self._placed[key] = found
        return found

    def normal_gradient(self, link: int, point, normal) -> np.ndarray:
        """normal . d point / d q for a point attached to chain link `link`."""
        if self._axes is None:
            axes, o = self.chain.joint_axes(self.frames)
            a = axes
            moments = np.stack([o[:, 1] * a[:, 2] - o[:, 2] * a[:, 1],
                                o[:, 2] * a[:, 0] - o[:, 0] * a[:, 2],
                                o[:, 0] * a[:, 1] - o[:, 1] * a[:, 0]], axis=1)
            self._axes = (axes, moments)
        axes, moments = self._axes
        # n . (a x (p - o)) = a . (p x n) + n . (o x a)
        p, n = point, normal
        pxn = np.array([p[1] * n[2] - p[2] * n[1], p[2] * n[0] - p[0] * n[2],
                        p[0] * n[1] - p[1] * n[0]])
        g = axes @ pxn + moments @ n
        if self.chain._has_prismatic:
            g = np.where(self.chain.revolute, g, axes @ n)
        return g * self.chain.moved_by[link]


class CollisionChecker:
    """Distance queries on a World; holds FCL objects, never touches PyBullet after init."""

    def __init__(self, world):
        self.world = world
        chain = world.chain
        self.n = world.n
        self._request = fcl.DistanceRequest(enable_nearest_points=True,
                                            enable_signed_distance=True)
        self.link_parts: list[Part] = robot_parts(world)
        self.body_shapes = {b.name: body_shapes(world, b) for b in world.scene.bodies}
        self.body_parts: dict[str, list[Part]] = {
            name: [Part(f"body:{name}", s, fcl_object(s), body=name) for s in shapes]
            for name, shapes in self.body_shapes.items()}
        self._held_parts: dict[str, list[Part]] = {}
        self._start = {b.name: b.matrix for b in world.scene.bodies}
        self.fixed = {b.name for b in world.scene.bodies if b.fixed}
        self.group = rigid_groups(chain)
        self._tool = chain.index[world.tool_link]
        self.tool_group = self.group[self._tool]
        self.support = find_support(world, self.fixed)
        self.slides = world.scene.robot.model == "planar"  # the whole robot rests on its support
        self._radii = np.array([p.shape.radius for p in self.link_parts])
        self._static_link = np.array([self.group[p.link] == 0 for p in self.link_parts])
        self._in_tool_group = np.array([self.group[p.link] == self.tool_group
                                        for p in self.link_parts])
        self.self_pairs = self._self_pairs()
        self._self_a = np.array([a for a, _ in self.self_pairs], dtype=int)
        self._self_b = np.array([b for _, b in self.self_pairs], dtype=int)

    # ------------------------------------------------------------ setup

    def _self_pairs(self) -> tuple[tuple[int, int], ...]:
        """Link-part pairs checked for self-collision (see the module docstring)."""
        chain = self.world.chain
        parent_group = {i: self.group[link.parent] for i, link in enumerate(chain.links)
                        if link.q_index >= 0}
        query = _Query(chain, self._default_configuration())
        pairs = []
        for ia, pa in enumerate(self.link_parts):
            for ib in range(ia + 1, len(self.link_parts)):
                pb_ = self.link_parts[ib]
                ga, gb = self.group[pa.link], self.group[pb_.link]
                if ga == gb or parent_group.get(ga) == gb or parent_group.get(gb) == ga:
                    continue
                a, b = query.placed(ia, pa, None), query.placed(ib, pb_, None)
                if signed_distance(self._request, a, pa.obj, b, pb_.obj)[0] > SELF_MARGIN:
                    pairs.append((ia, ib))
        return tuple(pairs)

    @property
    def self_pair_names(self) -> tuple[tuple[str, str], ...]:
        return tuple((self.link_parts[a].owner, self.link_parts[b].owner)
                     for a, b in self.self_pairs)

    def _default_configuration(self) -> np.ndarray:
        world = self.world
        if world.scene.robot.model == "panda":
            return np.array(PANDA_READY)
        mid = 0.5 * (world.lower + world.upper)
        return np.where(np.isfinite(mid), mid, 0.0)

    def _held(self, name: str) -> list[Part]:
        if name not in self._held_parts:
            self._held_parts[name] = [Part(f"held:{name}", s, fcl_object(s), body=name)
                                      for s in self.body_shapes[name]]
        return self._held_parts[name]

    # ------------------------------------------------------------ queries

    def distances(self, q, body_poses: dict | None = None, held=None,
                  ignore: frozenset[str] = frozenset(), activation: float = 0.05,
                  static: bool = False) -> list[Contact]:
        """Contacts of all covered pairs whose distance is at most `activation`.

        `body_poses`: name -> 4x4 (or xyz+quat) for bodies not at their start
        pose. `held`: (name, grasp), grasp = the object's pose in the tool
        frame. `ignore`: names ("wall", "body:wall", "link:panda_hand") left out.
        """
        query = _Query(self.world.chain, np.asarray(q, dtype=float))
        frames = query.frames
        held_name, held_pose = self._held_pose(frames, held)
        poses = self._body_poses(body_poses)
        out: list[Contact] = []
        parts = self.link_parts
        centers = np.array([frames[p.link][:3, :3] @ p.shape.center + frames[p.link][:3, 3]
                            for p in parts])
        usable = np.array([not _ignored(p, ignore) for p in parts])
        # Robot links vs bodies.
        for name, body_parts in self.body_parts.items():
            if name == held_name or name in ignore or f"body:{name}" in ignore:
                continue
            pose = poses[name]
            allowed = usable.copy()
            if name in self.support:
                allowed &= False if self.slides else ~self._static_link
            elif name in self.fixed and not static:
                allowed &= ~self._static_link
            for k, bp in enumerate(body_parts):
                c = pose[:3, :3] @ bp.shape.center + pose[:3, 3]
                gaps = np.linalg.norm(centers - c, axis=1) - self._radii - bp.shape.radius
                for i in np.nonzero((gaps <= activation) & allowed)[0]:
                    self._pair(query, out, activation, (i, parts[i], None),
                               (("body", name, k), bp, pose))
        if held_name is not None:
            self._held_pairs(query, out, activation, held_name, held_pose, poses, ignore,
                             centers, usable)
        # Self-collision.
        if len(self._self_a):
            ia, ib = self._self_a, self._self_b
            gaps = (np.linalg.norm(centers[ia] - centers[ib], axis=1)
                    - self._radii[ia] - self._radii[ib])
            for k in np.nonzero((gaps <= activation) & usable[ia] & usable[ib])[0]:
                a, b = int(ia[k]), int(ib[k])
                self._pair(query, out, activation, (a, parts[a], None), (b, parts[b], None))
        return out

    def _held_pairs(self, query, out, activation, held_name, held_pose, poses, ignore,
                    centers, usable):
        for h, hp in enumerate(self._held(held_name)):
            hc = held_pose[:3, :3] @ hp.shape.center + held_pose[:3, 3]
            held_side = (("held", h), hp, held_pose)
            for name, body_parts in self.body_parts.items():
                if name == held_name or name in ignore or f"body:{name}" in ignore:
                    continue
                pose = poses[name]
                for k, bp in enumerate(body_parts):
                    c = pose[:3, :3] @ bp.shape.center + pose[:3, 3]
                    if np.linalg.norm(hc - c) - hp.shape.radius - bp.shape.radius <= activation:
                        self._pair(query, out, activation, held_side,
                                   (("body", name, k), bp, pose))
            gaps = np.linalg.norm(centers - hc, axis=1) - self._radii - hp.shape.radius
            for i in np.nonzero((gaps <= activation) & usable & ~self._in_tool_group)[0]:
                self._pair(query, out, activation, held_side, (i, self.link_parts[i], None))

    def _pair(self, query, out, activation, side_a, side_b) -> None:
        """Narrow phase of one pair if its certified lower bound is within activation."""
        key_a, pa, pose_a = side_a
        key_b, pb_, pose_b = side_b
        a, b = query.placed(key_a, pa, pose_a), query.placed(key_b, pb_, pose_b)
        axis = b.t[:3, 3] - a.t[:3, 3]
        norm = math.sqrt(float(axis @ axis))
        if norm > 1e-9 and -overlap(a, b, axis / norm) > activation:
            return
        contact = self._contact(query, pa, a, pb_, b)
        if contact.distance <= activation:
            out.append(contact)

    def _contact(self, query, pa: Part, a: Placed, pb_: Part, b: Placed) -> Contact:
        d, p1, p2, n = signed_distance(self._request, a, pa.obj, b, pb_.obj)
        grad = np.zeros(self.n)
        link_a, link_b = self._moving_link(pa), self._moving_link(pb_)
        if link_a is not None:
            grad -= query.normal_gradient(link_a, p1, n)
        if link_b is not None:
            grad += query.normal_gradient(link_b, p2, n)
        return Contact(pa.owner, pb_.owner, d, p1, p2, n, grad)

    def _moving_link(self, part: Part) -> int | None:
        if part.link >= 0:
            return part.link
        if part.owner.startswith("held:"):
            return self._tool
        return None

    def min_distance(self, q, body_poses=None, held=None, ignore=frozenset(),
                     static: bool = True, horizon: float = 1.0) -> float:
        """Smallest signed distance over covered pairs (inf when none is within `horizon`)."""
        contacts = self.distances(q, body_poses, held, ignore, horizon, static)
        return min((c.distance for c in contacts), default=math.inf)

    def pair_distance(self, q, a: str, b: str, body_poses=None, held=None) -> Contact:
        """The contact of one named pair ("link:..", "held:..", "body:.."), however far apart.

        For owners made of several shapes, the closest pair of shapes.
        """
        query = _Query(self.world.chain, np.asarray(q, dtype=float))
        held_name, held_pose = self._held_pose(query.frames, held)
        poses = self._body_poses(body_poses)
        best = None
        for key_a, pa, pose_a in self._resolve(a, poses, held_name, held_pose):
            for key_b, pb_, pose_b in self._resolve(b, poses, held_name, held_pose):
                c = self._contact(query, pa, query.placed(key_a, pa, pose_a), pb_,
                                  query.placed(key_b, pb_, pose_b))
                if best is None or c.distance < best.distance:
                    best = c
        if best is None:
            raise KeyError(f"no collision geometry for {a!r} or {b!r}")
        return best

    def body_distance(self, name_a: str, pose_a, name_b: str, pose_b) -> Contact:
        """Distance between two scene bodies at given 4x4 poses.

        `gradient` (6,) is w.r.t. (x_a, y_a, yaw_a, x_b, y_b, yaw_b), yaw about
        world z through each body's origin.
        """
        pose_a, pose_b = np.asarray(pose_a, float), np.asarray(pose_b, float)
        best = None
        for pa in self.body_parts[name_a]:
            for pb_ in self.body_parts[name_b]:
                a = Placed(pa.shape, pose_a @ pa.shape.local)
                b = Placed(pb_.shape, pose_b @ pb_.shape.local)
                d, p1, p2, n = signed_distance(self._request, a, pa.obj, b, pb_.obj)
                if best is None or d < best[0]:
                    best = (d, p1, p2, n)
        d, p1, p2, n = best
        ra, rb = p1 - pose_a[:3, 3], p2 - pose_b[:3, 3]
        # d/dyaw of a point r about z: (-r_y, r_x, 0).
        grad = np.array([-n[0], -n[1], -(n[1] * ra[0] - n[0] * ra[1]),
                         n[0], n[1], n[1] * rb[0] - n[0] * rb[1]])
        return Contact(f"body:{name_a}", f"body:{name_b}", d, p1, p2, n, grad)

    # ------------------------------------------------------------ internals

    def _held_pose(self, frames, held):
        if held is None:
            return None, None
        name, grasp = held
        return name, frames[self._tool] @ np.asarray(grasp, dtype=float)

    def _body_poses(self, body_poses) -> dict[str, np.ndarray]:
        if not body_poses:
            return self._start
        poses = dict(self._start)
        for name, t in body_poses.items():
            t = np.asarray(t, dtype=float)
            poses[name] = transforms.pose_from_xyzquat(t) if t.shape == (7,) else t
        return poses

    def _resolve(self, name, poses, held_name, held_pose):
        kind, _, bare = name.partition(":")
        if kind == "link":
            return [(i, p, None) for i, p in enumerate(self.link_parts) if p.owner == name]
        if kind == "held":
            if bare != held_name:
                raise KeyError(f"{name!r} is not held")
            return [(("held", h), p, held_pose) for h, p in enumerate(self._held(bare))]
        if kind == "body":
            return [(("body", bare, k), p, poses[bare])
                    for k, p in enumerate(self.body_parts[bare])]
        raise KeyError(f"unknown name {name!r}: expected link:, held: or body:")


def _ignored(part: Part, ignore) -> bool:
    return part.owner in ignore or part.owner.partition(":")[2] in ignore
