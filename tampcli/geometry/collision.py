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

Broad phase: world-aligned bounding boxes of all pairs at once, then a
certified lower bound (the widest gap between the two solids' projections
on the line between their centres and on the normals of a box's faces); a
pair goes to the narrow phase (narrow.py: FCL, checked) only when both are
within `activation`. Distances are signed (negative
= penetration depth). `normal` points from a to b; `gradient` = d distance
/ d q = -normal . J_a(point_a) (+ normal . J_b(point_b) when b moves with q).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import fcl
import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.narrow import Placed, separation_bound, signed_distance
from tampcli.geometry.parts import (
    Part,
    body_shapes,
    box_gaps,
    fcl_object,
    find_support,
    rigid_groups,
    robot_parts,
    world_boxes,
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

    def __init__(self, chain, q, static_placed: dict | None = None):
        self.chain = chain
        self.frames = chain.fk_list(q)
        self._axes = None
        # Bodies at their start pose are placed once per checker, not per query.
        self._placed: dict = dict(static_placed) if static_placed else {}

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
            self._axes = self.chain.normal_gradient_basis(self.frames)
        p0, p1, p2 = point.tolist()
        n0, n1, n2 = normal.tolist()
        v = np.array([p1 * n2 - p2 * n1, p2 * n0 - p0 * n2, p0 * n1 - p1 * n0, n0, n1, n2])
        return (self._axes @ v) * self.chain.moved_mask[link]


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
        self._static_link = np.array([self.group[p.link] == 0 for p in self.link_parts])
        self._all_links = np.ones(len(self.link_parts), dtype=bool)
        self._in_tool_group = np.array([self.group[p.link] == self.tool_group
                                        for p in self.link_parts])
        self.self_pairs = self._self_pairs()
        self._self_a = np.array([a for a, _ in self.self_pairs], dtype=int)
        self._self_b = np.array([b for _, b in self.self_pairs], dtype=int)
        # Flat list of body parts, for a vectorized broad phase.
        self._flat = [(name, k, part) for name, parts in self.body_parts.items()
                      for k, part in enumerate(parts)]
        self._flat_of = {}
        for j, (name, _, _) in enumerate(self._flat):
            self._flat_of.setdefault(name, []).append(j)
        self._box_c = np.array([p.box_center for p in self.link_parts]).reshape(-1, 3)
        self._box_h = np.array([p.box_half for p in self.link_parts]).reshape(-1, 3)
        self._body_box_c, self._body_box_h = self._body_boxes(self._start)
        self._sphere_c = np.array([p.shape.center for p in self.link_parts]).reshape(-1, 3)
        self._sphere_r = np.array([p.shape.radius for p in self.link_parts])
        self._body_sphere_c = self._body_spheres(self._start)
        self._body_sphere_r = np.array([p.shape.radius for _, _, p in self._flat])
        self._static_placed = {
            ("body", name, k): Placed(part.shape, self._start[name] @ part.shape.local)
            for name, k, part in self._flat}
        # Which link-body pairs are covered (rows: link parts; columns: body parts).
        self._covered = {}
        for static in (False, True):
            covered = np.ones((len(self.link_parts), len(self._flat)), dtype=bool)
            for j, (name, _, _) in enumerate(self._flat):
                if name in self.support:
                    covered[:, j] = False if self.slides else ~self._static_link
                elif name in self.fixed and not static:
                    covered[:, j] = ~self._static_link
            self._covered[static] = covered

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
        query = self._query(q, body_poses)
        frames = query.frames
        held_name, held_pose = self._held_pose(frames, held)
        poses = self._body_poses(body_poses)
        out: list[Contact] = []
        parts = self.link_parts
        usable = (np.array([not _ignored(p, ignore) for p in parts]) if ignore
                  else self._all_links)
        # Robot links vs bodies: bounding boxes and spheres of all pairs at once;
        # each gives a lower bound on the distance, their maximum is used.
        link_frames = np.array([frames[p.link] for p in parts])
        link_c, link_h = world_boxes(link_frames, self._box_c, self._box_h)
        link_s = np.einsum("kij,kj->ki", link_frames[:, :3, :3], self._sphere_c) \
            + link_frames[:, :3, 3]
        body_c, body_h, body_s = self._body_box_c, self._body_box_h, self._body_sphere_c
        columns = np.ones(len(self._flat), dtype=bool)
        if body_poses:
            rows = [j for name in body_poses for j in self._flat_of.get(name, ())]
            if rows:
                body_c, body_h, body_s = body_c.copy(), body_h.copy(), body_s.copy()
                body_c[rows], body_h[rows] = self._body_boxes(poses, rows)
                body_s[rows] = self._body_spheres(poses, rows)
        for name in (held_name, *ignore):
            bare = name.partition(":")[2] if name and name.startswith("body:") else name
            for j in self._flat_of.get(bare, ()):
                columns[j] = False
        spheres = (np.linalg.norm(link_s[:, None, :] - body_s[None, :, :], axis=2)
                   - self._sphere_r[:, None] - self._body_sphere_r[None, :])
        close = np.maximum(box_gaps(link_c, link_h, body_c, body_h), spheres) <= activation
        close &= self._covered[bool(static)]
        close &= usable[:, None] & columns[None, :]
        for i, j in zip(*np.nonzero(close), strict=True):
            name, k, bp = self._flat[j]
            self._pair(query, out, activation, (int(i), parts[i], None),
                       (("body", name, k), bp, poses[name]))
        if held_name is not None:
            self._held_pairs(query, out, activation, held_name, held_pose, poses,
                             (link_c, link_h), (body_c, body_h), columns, usable)
        # Self-collision.
        if len(self._self_a):
            ia, ib = self._self_a, self._self_b
            apart = np.abs(link_c[ia] - link_c[ib]) - link_h[ia] - link_h[ib]
            gaps = np.maximum(
                np.sqrt((np.maximum(apart, 0.0) ** 2).sum(axis=1)),
                np.linalg.norm(link_s[ia] - link_s[ib], axis=1)
                - self._sphere_r[ia] - self._sphere_r[ib])
            for k in np.nonzero((gaps <= activation) & usable[ia] & usable[ib])[0]:
                a, b = int(ia[k]), int(ib[k])
                self._pair(query, out, activation, (a, parts[a], None), (b, parts[b], None))
        return out

    def _held_pairs(self, query, out, activation, held_name, held_pose, poses, links, bodies,
                    columns, usable):
        """Held object vs bodies and vs links outside the tool's rigid group."""
        link_c, link_h = links
        body_c, body_h = bodies
        for h, hp in enumerate(self._held(held_name)):
            hc, hh = world_boxes(held_pose[None], hp.box_center[None], hp.box_half[None])
            held_side = (("held", h), hp, held_pose)
            near = (box_gaps(hc, hh, body_c, body_h)[0] <= activation) & columns
            for j in np.nonzero(near)[0]:
                name, k, bp = self._flat[j]
                self._pair(query, out, activation, held_side,
                           (("body", name, k), bp, poses[name]))
            near = (box_gaps(hc, hh, link_c, link_h)[0] <= activation) & usable
            for i in np.nonzero(near & ~self._in_tool_group)[0]:
                self._pair(query, out, activation, held_side, (i, self.link_parts[i], None))

    def _pair(self, query, out, activation, side_a, side_b) -> None:
        """Narrow phase of one pair if its certified lower bound is within activation."""
        key_a, pa, pose_a = side_a
        key_b, pb_, pose_b = side_b
        a, b = query.placed(key_a, pa, pose_a), query.placed(key_b, pb_, pose_b)
        if separation_bound(a, b) > activation:
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
        query = self._query(q, body_poses)
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

    def _body_boxes(self, poses, rows=None):
        flat = self._flat if rows is None else [self._flat[j] for j in rows]
        if not flat:
            return np.zeros((0, 3)), np.zeros((0, 3))
        frames = np.array([poses[name] for name, _, _ in flat])
        return world_boxes(frames, np.array([p.box_center for _, _, p in flat]),
                           np.array([p.box_half for _, _, p in flat]))

    def _body_spheres(self, poses, rows=None) -> np.ndarray:
        flat = self._flat if rows is None else [self._flat[j] for j in rows]
        return np.array([poses[name][:3, :3] @ p.shape.center + poses[name][:3, 3]
                         for name, _, p in flat]).reshape(-1, 3)

    def _query(self, q, body_poses) -> _Query:
        placed = self._static_placed
        if body_poses:
            placed = {key: v for key, v in placed.items() if key[1] not in body_poses}
        return _Query(self.world.chain, np.asarray(q, dtype=float), placed)

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
