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

Broad phase, for a batch of configurations at once (`distances_many`): the
links' frames by one batched forward kinematics, then world-aligned boxes and
bounding spheres of every (row, part, body) triple, then the oriented-box and
hull-point gaps of the survivors (broad.py, obb.py), all as array operations;
only pairs whose bounds are within `activation` reach the narrow phase
(pairs.py: FCL per pair, its answers checked (certify.py) and the gradients
taken for all pairs together; narrow.py, prism.py). Distances are signed (negative
= penetration depth). `normal` points from a to b; `gradient` = d distance
/ d q = -normal . J_a(point_a) (+ normal . J_b(point_b) when b moves with q).
"""

from __future__ import annotations

import copy
import math

import fcl
import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.broad import Boxes, PartTable, broad_gaps, masks, screen
from tampcli.geometry.coal_query import CoalDistance
from tampcli.geometry.narrow import Placed, signed_distance
from tampcli.geometry.pairs import Batch, Contact, Query, Side
from tampcli.geometry.parts import (
    Part,
    body_shapes,
    fcl_object,
    find_support,
    rigid_groups,
    robot_parts,
)
from tampcli.geometry.self_pairs import SELF_MARGIN, self_collision_pairs

__all__ = ["CollisionChecker", "Contact", "SELF_MARGIN"]


class CollisionChecker:
    """Distance queries on a World; holds FCL objects, never touches PyBullet after init."""

    def __init__(self, world):
        self.world = world
        chain = world.chain
        self.n = world.n
        self._request = fcl.DistanceRequest(enable_nearest_points=True,
                                            enable_signed_distance=True)
        self.coal = CoalDistance()  # narrow.certified's second opinion
        self.link_parts: list[Part] = robot_parts(world)
        self.body_shapes = {b.name: body_shapes(world, b) for b in world.scene.bodies}
        self.body_parts: dict[str, list[Part]] = {
            name: [Part(f"body:{name}", s, fcl_object(s), body=name) for s in shapes]
            for name, shapes in self.body_shapes.items()}
        self._held_parts: dict[str, PartTable] = {}
        # The finger joints' values (World.finger_links' order) every query takes
        # unless told otherwise; None: as loaded, open (`with_fingers`).
        self.fingers: tuple[float, ...] | None = None
        self._start = {b.name: b.matrix for b in world.scene.bodies}
        self.fixed = {b.name for b in world.scene.bodies if b.fixed}
        self.group = rigid_groups(chain)
        self._tool = chain.index[world.tool_link]
        self.tool_group = self.group[self._tool]
        self.support = find_support(world, self.fixed)
        self.slides = world.scene.robot.model == "planar"  # the whole robot rests on its support
        self._static_link = np.array([self.group[p.link] == 0 for p in self.link_parts])
        self._in_tool_group = np.array([self.group[p.link] == self.tool_group
                                        for p in self.link_parts])
        self.self_pairs = self_collision_pairs(world, self.link_parts, self.group,
                                               self._request)
        self._self_a = np.array([a for a, _ in self.self_pairs], dtype=int)
        self._self_b = np.array([b for _, b in self.self_pairs], dtype=int)
        # Flat list of body parts, for a vectorized broad phase.
        self._flat = [(name, k, part) for name, parts in self.body_parts.items()
                      for k, part in enumerate(parts)]
        self._flat_of = {}
        for j, (name, _, _) in enumerate(self._flat):
            self._flat_of.setdefault(name, []).append(j)
        self._link_index = np.array([p.link for p in self.link_parts], dtype=int)
        self._link_table = PartTable.of(self.link_parts)
        self._body_table = PartTable.of(p for _, _, p in self._flat)
        # The screens bound the cores; two rounded solids are closer by their margins.
        every = (*self.link_parts, *(p for _, _, p in self._flat))
        self._pad = 2.0 * max((p.shape.margin for p in every), default=0.0)
        self._body_start = self._body_boxes(self._start)
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

    @property
    def self_pair_names(self) -> tuple[tuple[str, str], ...]:
        return tuple((self.link_parts[a].owner, self.link_parts[b].owner)
                     for a, b in self.self_pairs)

    def _held(self, name: str) -> PartTable:
        if name not in self._held_parts:
            self._held_parts[name] = PartTable.of(
                Part(f"held:{name}", s, fcl_object(s), body=name) for s in self.body_shapes[name])
        return self._held_parts[name]

    def with_fingers(self, values) -> CollisionChecker:
        """This checker with the fingers held at `values` (one per World.finger_links)
        in every query: a hand opened only as wide as a skeleton's objects need
        (optimize/hand.py). It shares this one's shapes and caches; None: open."""
        if values is None and self.fingers is None:
            return self
        out = copy.copy(self)
        out.fingers = None if values is None else tuple(float(v) for v in values)
        return out

    def _frames(self, qs: np.ndarray, fingers=None) -> np.ndarray:
        """fk_batch frames of the rows of qs, the fingers at `fingers` ((S, k) per row)
        or else at this checker's own values."""
        chain = self.world.chain
        frames = chain.fk_batch(qs)
        if fingers is None and self.fingers is not None:
            fingers = np.broadcast_to(np.asarray(self.fingers), (len(qs), len(self.fingers)))
        if fingers is not None:
            values = np.asarray(fingers, dtype=float).reshape(len(qs), -1)
            frames = chain.refixed(frames, dict(zip(self.world.finger_links, values.T,
                                                    strict=True)))
        return frames

    # ------------------------------------------------------------ queries

    def distances(self, q, body_poses: dict | None = None, held=None,
                  ignore: frozenset[str] = frozenset(), activation: float = 0.05,
                  static: bool = False) -> list[Contact]:
        """Contacts of all covered pairs whose distance is at most `activation`.

        `body_poses`: name -> 4x4 (or xyz+quat) for bodies not at their start
        pose. `held`: (name, grasp), grasp = the object's pose in the tool
        frame. `ignore`: names ("wall", "body:wall", "link:panda_hand") left out.
        """
        q = np.asarray(q, dtype=float).reshape(1, -1)
        return self.distances_many(q, body_poses, held, [ignore], activation, static)[0]

    def distances_many(self, qs, body_poses=None, held=None, ignores=None,
                       activation: float = 0.05, static: bool = False,
                       fingers=None) -> list[list[Contact]]:
        """`distances` for each row of qs (S, n) at once: one list of contacts per row.

        `body_poses` and `held` are either one value for all rows (as in
        `distances`) or a list with one value per row (keyframes, each in its
        own state of the world). `ignores`: one set of names per row (or None:
        nothing ignored). `fingers`: (S, k) values of the finger joints
        (World.finger_links' order) per row, where a solution file gives them;
        None: this checker's (`with_fingers`; open unless set).
        """
        qs = np.asarray(qs, dtype=float).reshape(-1, self.n)
        n_samples = len(qs)
        ignores = [frozenset()] * n_samples if ignores is None else list(ignores)
        per_row = isinstance(body_poses, list | tuple)
        helds = list(held) if isinstance(held, list) else [held] * n_samples
        frames = self._frames(qs, fingers)
        if per_row:
            bodies = self._body_boxes_rows([self._body_poses(bp) for bp in body_poses],
                                           [frozenset(bp or ()) for bp in body_poses])
        else:
            bodies = self._start_or_moved(body_poses, self._body_poses(body_poses))
        batch = Batch(self, frames, activation)
        reach = activation + self._pad
        usable, columns = masks(self.link_parts, len(self._flat), self._flat_of, ignores,
                                [h[0] if h else None for h in helds])
        links = Boxes(frames[:, self._link_index], self._link_table)
        link_moves = self._link_index

        def body_index(s_):
            return s_ if per_row else np.zeros_like(s_)

        # Robot links vs bodies.
        near = broad_gaps(links.c[:, :, None], links.aabb[:, :, None], links.s[:, :, None],
                          links.radius[None, :, None], bodies.c[:, None], bodies.aabb[:, None],
                          bodies.s[:, None], bodies.radius) <= reach
        near &= self._covered[bool(static)] & usable[:, :, None] & columns[:, None, :]
        s_, i_, j_ = np.nonzero(near)
        keep = screen(reach, links, (s_, i_), i_, bodies, (body_index(s_), j_), j_)
        s_, i_, j_ = s_[keep], i_[keep], j_[keep]
        batch.narrow(s_, Side(links.table, i_, links.frames[s_, i_], link_moves[i_]),
                     Side(bodies.table, j_, bodies.frames[body_index(s_), j_], None))
        for name in sorted({h[0] for h in helds if h is not None}):
            rows = np.array([s for s, h in enumerate(helds) if h is not None and h[0] == name])
            grasps = np.array([np.asarray(helds[s][1], dtype=float) for s in rows])
            self._held_pairs(batch, name, rows, grasps, frames, links, bodies, per_row,
                             columns, usable)
        if len(self._self_a):
            ia, ib = self._self_a, self._self_b
            gap = broad_gaps(links.c[:, ia], links.aabb[:, ia], links.s[:, ia], links.radius[ia],
                             links.c[:, ib], links.aabb[:, ib], links.s[:, ib], links.radius[ib])
            near = (gap <= reach) & usable[:, ia] & usable[:, ib]
            s_, k_ = np.nonzero(near)
            a_, b_ = ia[k_], ib[k_]
            keep = screen(reach, links, (s_, a_), a_, links, (s_, b_), b_)
            s_, a_, b_ = s_[keep], a_[keep], b_[keep]
            batch.narrow(s_, Side(links.table, a_, links.frames[s_, a_], link_moves[a_]),
                         Side(links.table, b_, links.frames[s_, b_], link_moves[b_]))
        return batch.out

    def _held_pairs(self, batch, name, rows, grasps, frames, links, bodies, per_row, columns,
                    usable):
        """Object `name` held at rows `rows` (grasps (G, 4, 4)) vs bodies and vs the
        links outside the tool's rigid group."""
        reach = batch.activation + self._pad
        held_poses = frames[rows, self._tool] @ grasps  # (G, 4, 4)
        table = self._held(name)
        # One frame per (row, part): the hull screen indexes frames by both (a mesh of
        # several convex parts held: blind29 p03's duck, an IndexError before).
        boxes = Boxes(np.broadcast_to(held_poses[:, None], (len(held_poses), len(table.parts),
                                                            4, 4)), table)  # (G, H, ...)
        tool = np.full(len(table.parts), self._tool)
        # Vs bodies (per row when each row has its own world state).
        b = bodies
        brow = rows if per_row else np.zeros(len(rows), dtype=int)
        gap = broad_gaps(boxes.c[:, :, None], boxes.aabb[:, :, None], boxes.s[:, :, None],
                         boxes.radius[None, :, None], b.c[brow][:, None], b.aabb[brow][:, None],
                         b.s[brow][:, None], b.radius)
        g_, h_, j_ = np.nonzero((gap <= reach) & columns[rows][:, None, :])
        keep = screen(reach, boxes, (g_, h_), h_, b, (brow[g_], j_), j_)
        g_, h_, j_ = g_[keep], h_[keep], j_[keep]
        batch.narrow(rows[g_], Side(table, h_, held_poses[g_], tool[h_]),
                     Side(b.table, j_, b.frames[brow[g_], j_], None))
        # Vs links.
        gap = broad_gaps(boxes.c[:, :, None], boxes.aabb[:, :, None], boxes.s[:, :, None],
                         boxes.radius[None, :, None], links.c[rows][:, None],
                         links.aabb[rows][:, None], links.s[rows][:, None], links.radius)
        mask = (usable & ~self._in_tool_group)[rows]
        g_, h_, j_ = np.nonzero((gap <= reach) & mask[:, None, :])
        keep = screen(reach, boxes, (g_, h_), h_, links, (rows[g_], j_), j_)
        g_, h_, j_ = g_[keep], h_[keep], j_[keep]
        s_ = rows[g_]
        batch.narrow(s_, Side(table, h_, held_poses[g_], tool[h_]),
                     Side(links.table, j_, links.frames[s_, j_], self._link_index[j_]))

    def _contact(self, query, pa: Part, a: Placed, pb_: Part, b: Placed) -> Contact:
        d, p1, p2, n = signed_distance(self._request, a, pa.obj, b, pb_.obj, self.coal)
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
                d, p1, p2, n = signed_distance(self._request, a, pa.obj, b, pb_.obj, self.coal)
                if best is None or d < best[0]:
                    best = (d, p1, p2, n)
        d, p1, p2, n = best
        ra, rb = p1 - pose_a[:3, 3], p2 - pose_b[:3, 3]
        # d/dyaw of a point r about z: (-r_y, r_x, 0).
        grad = np.array([-n[0], -n[1], -(n[1] * ra[0] - n[0] * ra[1]),
                         n[0], n[1], n[1] * rb[0] - n[0] * rb[1]])
        return Contact(f"body:{name_a}", f"body:{name_b}", d, p1, p2, n, grad)

    # ------------------------------------------------------------ internals

    def _body_boxes(self, poses) -> Boxes:
        """Boxes of all body parts in one world state, with a leading row axis of 1."""
        frames = np.array([poses[name] for name, _, _ in self._flat]).reshape(1, -1, 4, 4)
        return Boxes(frames, self._body_table)

    def _body_boxes_rows(self, poses: list[dict], moved: list[frozenset]) -> Boxes:
        """Boxes of all body parts in each row's world state: leading axis S."""
        if not any(moved):
            return Boxes(np.broadcast_to(self._body_start.frames,
                                          (len(poses), *self._body_start.frames.shape[1:])),
                         self._body_table)
        frames = np.array([[p[name] for name, _, _ in self._flat] for p in poses])
        return Boxes(frames.reshape(len(poses), -1, 4, 4), self._body_table)

    def _start_or_moved(self, body_poses, poses) -> Boxes:
        if not body_poses or not any(name in self._flat_of for name in body_poses):
            return self._body_start
        return self._body_boxes(poses)

    def _shared_placed(self, body_poses) -> dict:
        if not body_poses:
            return dict(self._static_placed)
        return {key: v for key, v in self._static_placed.items() if key[1] not in body_poses}

    def _query(self, q, body_poses) -> Query:
        chain = self.world.chain
        q = np.asarray(q, dtype=float)
        frames = chain.fk_list(q) if self.fingers is None else list(
            self._frames(q.reshape(1, -1))[0])
        return Query(chain, frames, self._shared_placed(body_poses))

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
            return [(("held", h), p, held_pose) for h, p in enumerate(self._held(bare).parts)]
        if kind == "body":
            return [(("body", bare, k), p, poses[bare])
                    for k, p in enumerate(self.body_parts[bare])]
        raise KeyError(f"unknown name {name!r}: expected link:, held: or body:")

