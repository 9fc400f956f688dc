"""Signed distances, witness points, normals and joint gradients (python-fcl).

Pairs covered by `CollisionChecker.distances`:

- robot link vs scene body (every body except the held one and `ignore`);
- held object vs scene body, and held object vs robot links outside the
  tool's rigid group (the hand and fingers touch what they hold);
- robot self-collision between links of rigid groups that are not adjacent
  (adjacent = one joint apart), except pairs closer than SELF_MARGIN in the
  robot's default configuration (the Panda's "ready" pose, otherwise the
  middle of the joint limits): those touch by construction of the meshes.
- Not covered: the robot's base group against the body it stands on (its
  support: a fixed body whose top face is at the base height, within 5 mm,
  under the base), and pairs whose distance q cannot change (base-group
  links vs fixed bodies) unless `static=True`.

A pair is pruned by bounding spheres when their gap exceeds `activation`.
Distances are signed (negative = penetration depth). `normal` points from
a to b; `gradient` = d distance / d q = -normal . J_a(point_a) (+ normal .
J_b(point_b) when b moves with q too).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import fcl
import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.narrow import signed_distance
from tampcli.geometry.scene import PANDA_READY
from tampcli.geometry.shapes import Shape, fcl_transform, mesh_hull, primitive
from tampcli.geometry.shapes import pybullet_link_shapes as _link_shapes

SELF_MARGIN = 0.01  # m: link pairs this close in the default configuration are not checked
SUPPORT_TOLERANCE = 0.005  # m


@dataclass(frozen=True)
class Contact:
    a: str  # "link:NAME", "held:NAME" or "body:NAME"
    b: str
    distance: float  # signed, m; negative = penetration
    point_a: np.ndarray = field(repr=False)  # world witness point on a
    point_b: np.ndarray = field(repr=False)
    normal: np.ndarray = field(repr=False)  # unit, from a to b
    gradient: np.ndarray = field(repr=False)  # (n,) d distance / d q


@dataclass
class _Part:
    """One collision object: a shape on a link (link >= 0), a body or the held object."""

    owner: str
    shape: Shape
    obj: fcl.CollisionObject
    link: int = -1  # chain index for robot shapes
    body: str | None = None


class CollisionChecker:
    """Distance queries on a World; holds FCL objects, never touches PyBullet after init."""

    def __init__(self, world):
        self.world = world
        chain = world.chain
        self.n = world.n
        self._request = fcl.DistanceRequest(enable_nearest_points=True,
                                            enable_signed_distance=True)
        self.link_parts: list[_Part] = []
        pb, client = world.pb, world.client
        for i, link in enumerate(chain.links):
            for shape in _link_shapes(pb, client, world.robot_id, link.pb_index):
                self.link_parts.append(_Part(f"link:{link.name}", shape, _obj(shape), i))
        self.body_shapes: dict[str, list[Shape]] = {
            b.name: _body_shapes(world, b) for b in world.scene.bodies}
        self.body_parts: dict[str, list[_Part]] = {
            name: [_Part(f"body:{name}", s, _obj(s), body=name) for s in shapes]
            for name, shapes in self.body_shapes.items()}
        self._held_parts: dict[str, list[_Part]] = {}
        self._axes_cache = None
        self.fixed = {b.name for b in world.scene.bodies if b.fixed}
        self.group = _rigid_groups(chain)
        self.tool_group = self.group[chain.index[world.tool_link]]
        self.support = self._find_support()
        self.slides = world.scene.robot.model == "planar"  # the whole robot rests on its support
        self.self_pairs = self._self_pairs()

    # ------------------------------------------------------------ setup

    def _find_support(self) -> frozenset[str]:
        """Fixed bodies the robot stands (planar: slides) on."""
        world = self.world
        spec = world.scene.robot
        base = spec.base_pose[:3, 3]
        bottom = base[2] - (spec.height / 2 if spec.model == "planar" else 0.0)
        found = set()
        for name in self.fixed:
            lo, hi = world._aabb(world.pb_body(name))
            if abs(hi[2] - bottom) > SUPPORT_TOLERANCE:
                continue
            inside = lo[0] - 1e-9 <= base[0] <= hi[0] and lo[1] - 1e-9 <= base[1] <= hi[1]
            if inside or spec.model == "planar":
                found.add(name)
        return frozenset(found)

    def _self_pairs(self) -> tuple[tuple[int, int], ...]:
        """Link-part pairs checked for self-collision (see the module docstring)."""
        chain = self.world.chain
        parent_group = {}
        for i, link in enumerate(chain.links):
            if link.q_index >= 0:
                parent_group[i] = self.group[link.parent] if link.parent >= 0 else 0
        default = self._default_configuration()
        frames = chain.fk_list(default)
        pairs = []
        for ia, pa in enumerate(self.link_parts):
            for ib in range(ia + 1, len(self.link_parts)):
                pb_ = self.link_parts[ib]
                ga, gb = self.group[pa.link], self.group[pb_.link]
                if ga == gb or parent_group.get(ga) == gb or parent_group.get(gb) == ga:
                    continue
                d = self._narrow(pa, frames[pa.link], pb_, frames[pb_.link])[0]
                if d > SELF_MARGIN:
                    pairs.append((ia, ib))
        return tuple(pairs)

    def _default_configuration(self) -> np.ndarray:
        world = self.world
        if world.scene.robot.model == "panda":
            return np.array(PANDA_READY)
        mid = 0.5 * (world.lower + world.upper)
        return np.where(np.isfinite(mid), mid, 0.0)

    def _held(self, name: str) -> list[_Part]:
        if name not in self._held_parts:
            self._held_parts[name] = [_Part(f"held:{name}", s, _obj(s), body=name)
                                      for s in self.body_shapes[name]]
        return self._held_parts[name]

    # ------------------------------------------------------------ queries

    def distances(self, q, body_poses: dict | None = None, held=None,
                  ignore: frozenset[str] = frozenset(), activation: float = 0.05,
                  static: bool = False) -> list[Contact]:
        """Contacts of all covered pairs whose distance is at most `activation`.

        `body_poses`: name -> 4x4 for bodies not at their start pose. `held`:
        (name, grasp) with grasp = the object's pose in the tool frame.
        `ignore`: names ("wall", "body:wall", "link:panda_hand") left out.
        """
        q = np.asarray(q, dtype=float)
        frames = self.world.chain.fk_list(q)
        held_name, held_pose = self._held_pose(frames, held)
        poses = self._body_poses(body_poses)
        out: list[Contact] = []
        link_world = [frames[p.link] for p in self.link_parts]
        centers = np.array([t[:3, :3] @ p.shape.center + t[:3, 3]
                            for p, t in zip(self.link_parts, link_world, strict=True)])
        radii = np.array([p.shape.radius for p in self.link_parts])
        skip_links = np.array([_ignored(p, ignore) for p in self.link_parts])
        static_link = np.array([self.group[p.link] == 0 for p in self.link_parts])
        for name, parts in self.body_parts.items():
            if name == held_name or name in ignore or f"body:{name}" in ignore:
                continue
            pose = poses.get(name)
            fixed = name in self.fixed
            for part in parts:
                t = pose @ part.shape.local if pose is not None else None
                c = _center(part, pose)
                gaps = np.linalg.norm(centers - c, axis=1) - radii - part.shape.radius
                for i in np.nonzero((gaps <= activation) & ~skip_links)[0]:
                    lp = self.link_parts[i]
                    if name in self.support and (static_link[i] or self.slides):
                        continue
                    if static_link[i] and fixed and not static:
                        continue
                    contact = self._contact(lp, link_world[i], part, pose, frames, t)
                    if contact.distance <= activation:
                        out.append(contact)
        if held_name is not None:
            out.extend(self._held_contacts(held_name, held_pose, frames, poses, ignore,
                                           activation, link_world, centers, radii, skip_links))
        for ia, ib in self.self_pairs:
            pa, pb_ = self.link_parts[ia], self.link_parts[ib]
            if skip_links[ia] or skip_links[ib]:
                continue
            gap = np.linalg.norm(centers[ia] - centers[ib]) - radii[ia] - radii[ib]
            if gap > activation:
                continue
            contact = self._contact(pa, link_world[ia], pb_, None, frames, None,
                                    b_link_frame=link_world[ib])
            if contact.distance <= activation:
                out.append(contact)
        return out

    def min_distance(self, q, body_poses=None, held=None, ignore=frozenset(),
                     static: bool = True, horizon: float = 1.0) -> float:
        """Smallest signed distance over covered pairs (inf when none is within `horizon`)."""
        contacts = self.distances(q, body_poses, held, ignore, horizon, static)
        return min((c.distance for c in contacts), default=math.inf)

    def pair_distance(self, q, a: str, b: str, body_poses=None, held=None) -> Contact:
        """The contact of one named pair ("link:..", "held:..", "body:.."), however far apart.

        For multi-shape owners, the closest pair of shapes.
        """
        q = np.asarray(q, dtype=float)
        frames = self.world.chain.fk_list(q)
        held_name, held_pose = self._held_pose(frames, held)
        poses = self._body_poses(body_poses)
        best = None
        for pa, ta in self._resolve(a, frames, poses, held_name, held_pose):
            for pb_, tb in self._resolve(b, frames, poses, held_name, held_pose):
                c = self._generic_contact(pa, ta, pb_, tb, frames)
                if best is None or c.distance < best.distance:
                    best = c
        if best is None:
            raise KeyError(f"no collision geometry for {a!r} or {b!r}")
        return best

    def body_distance(self, name_a: str, pose_a, name_b: str, pose_b) -> Contact:
        """Distance between two scene bodies at given poses.

        `gradient` (6,) is w.r.t. (x_a, y_a, yaw_a, x_b, y_b, yaw_b), yaw about
        world z through each body's origin.
        """
        pose_a, pose_b = np.asarray(pose_a, float), np.asarray(pose_b, float)
        best = None
        for sa in self.body_shapes[name_a]:
            for sb in self.body_shapes[name_b]:
                ta, tb = pose_a @ sa.local, pose_b @ sb.local
                oa, ob = _obj(sa), _obj(sb)
                oa.setTransform(fcl_transform(ta))
                ob.setTransform(fcl_transform(tb))
                d, p1, p2, n = signed_distance(self._request, sa, oa, ta, sb, ob, tb)
                if best is None or d < best[0]:
                    best = (d, p1, p2, n)
        d, p1, p2, n = best
        ez = np.array([0.0, 0.0, 1.0])
        grad = np.array([
            -n[0], -n[1], -n @ np.cross(ez, p1 - pose_a[:3, 3]),
            n[0], n[1], n @ np.cross(ez, p2 - pose_b[:3, 3])])
        return Contact(f"body:{name_a}", f"body:{name_b}", d, p1, p2, n, grad)

    # ------------------------------------------------------------ internals

    def _held_pose(self, frames, held):
        if held is None:
            return None, None
        name, grasp = held
        tool = frames[self.world.chain.index[self.world.tool_link]]
        return name, tool @ np.asarray(grasp, dtype=float)

    def _body_poses(self, body_poses) -> dict[str, np.ndarray]:
        poses = {b.name: b.matrix for b in self.world.scene.bodies}
        for name, t in (body_poses or {}).items():
            t = np.asarray(t, dtype=float)
            poses[name] = transforms.pose_from_xyzquat(t) if t.shape == (7,) else t
        return poses

    def _held_contacts(self, held_name, held_pose, frames, poses, ignore, activation,
                       link_world, centers, radii, skip_links):
        out = []
        for hp in self._held(held_name):
            ht = held_pose @ hp.shape.local
            hc = _center(hp, held_pose)
            for name, parts in self.body_parts.items():
                if name == held_name or name in ignore or f"body:{name}" in ignore:
                    continue
                for part in parts:
                    c = _center(part, poses[name])
                    if np.linalg.norm(hc - c) - hp.shape.radius - part.shape.radius > activation:
                        continue
                    contact = self._generic_contact(hp, ht, part, poses[name] @ part.shape.local,
                                                    frames)
                    if contact.distance <= activation:
                        out.append(contact)
            gaps = np.linalg.norm(centers - hc, axis=1) - radii - hp.shape.radius
            for i in np.nonzero((gaps <= activation) & ~skip_links)[0]:
                lp = self.link_parts[i]
                if self.group[lp.link] == self.tool_group:
                    continue
                contact = self._generic_contact(hp, ht, lp, link_world[i] @ lp.shape.local,
                                                frames)
                if contact.distance <= activation:
                    out.append(contact)
        return out

    def _resolve(self, name, frames, poses, held_name, held_pose):
        kind, _, bare = name.partition(":")
        if kind == "link":
            return [(p, frames[p.link] @ p.shape.local) for p in self.link_parts
                    if p.owner == name]
        if kind == "held":
            if bare != held_name:
                raise KeyError(f"{name!r} is not held")
            return [(p, held_pose @ p.shape.local) for p in self._held(bare)]
        if kind == "body":
            return [(p, poses[bare] @ p.shape.local) for p in self.body_parts[bare]]
        raise KeyError(f"unknown name {name!r}: expected link:, held: or body:")

    def _contact(self, lp: _Part, link_frame, part: _Part, pose, frames, t_body,
                 b_link_frame=None) -> Contact:
        ta = link_frame @ lp.shape.local
        tb = (b_link_frame @ part.shape.local if b_link_frame is not None
              else t_body if t_body is not None else part.shape.local)
        return self._generic_contact(lp, ta, part, tb, frames)

    def _generic_contact(self, pa: _Part, ta, pb_: _Part, tb, frames) -> Contact:
        pa.obj.setTransform(fcl_transform(ta))
        pb_.obj.setTransform(fcl_transform(tb))
        d, p1, p2, n = signed_distance(self._request, pa.shape, pa.obj, ta, pb_.shape, pb_.obj, tb)
        grad = -n @ self._jacobian(pa, p1, frames) + n @ self._jacobian(pb_, p2, frames)
        return Contact(pa.owner, pb_.owner, d, p1, p2, n, grad)

    def _jacobian(self, part: _Part, point, frames) -> np.ndarray:
        chain = self.world.chain
        if part.link >= 0:
            link = part.link
        elif part.owner.startswith("held:"):
            link = chain.index[self.world.tool_link]
        else:
            return np.zeros((3, self.n))
        axes, origins = self._axes_for(frames)
        return chain.point_jacobian(axes, origins, link, point)

    def _axes_for(self, frames):
        # One query evaluates many Jacobians on the same frames: compute the
        # joint axes once per frames list.
        cached = self._axes_cache
        if cached is None or cached[0] is not frames:
            cached = (frames, self.world.chain.joint_axes(frames))
            self._axes_cache = cached
        return cached[1]

    def _narrow(self, pa: _Part, frame_a, pb_: _Part, frame_b):
        ta, tb = frame_a @ pa.shape.local, frame_b @ pb_.shape.local
        pa.obj.setTransform(fcl_transform(ta))
        pb_.obj.setTransform(fcl_transform(tb))
        return signed_distance(self._request, pa.shape, pa.obj, ta, pb_.shape, pb_.obj, tb)


def _obj(shape: Shape) -> fcl.CollisionObject:
    return fcl.CollisionObject(shape.geometry, fcl_transform(shape.local))


def _center(part: _Part, pose) -> np.ndarray:
    if pose is None:
        return part.shape.center
    return pose[:3, :3] @ part.shape.center + pose[:3, 3]


def _ignored(part: _Part, ignore) -> bool:
    return part.owner in ignore or part.owner.partition(":")[2] in ignore


def _body_shapes(world, body) -> list[Shape]:
    if body.shape in ("box", "cylinder", "sphere"):
        return [primitive(body.shape, body.size)]
    if body.shape == "mesh":
        return [mesh_hull(body.mesh, body.scale)]
    pb, client, uid = world.pb, world.client, world.pb_body(body.name)
    base_inv = transforms.pose_inverse(body.matrix)
    shapes = []
    for link in range(-1, pb.getNumJoints(uid, physicsClientId=client)):
        if link == -1:
            frame = np.eye(4)
        else:
            state = pb.getLinkState(uid, link, computeForwardKinematics=True,
                                    physicsClientId=client)
            frame = base_inv @ transforms.pose(transforms.quat_to_matrix(state[5]), state[4])
        for s in _link_shapes(pb, client, uid, link):
            local = frame @ s.local
            shapes.append(dataclasses.replace(s, local=local,
                                              center=frame[:3, :3] @ s.center + frame[:3, 3]))
    return shapes


def _rigid_groups(chain) -> list[int]:
    """Per link: the index of the link whose joint (a variable) last moves it; 0 = base."""
    group = [0] * len(chain.links)
    for i, link in enumerate(chain.links):
        if i == 0:
            continue
        group[i] = i if link.q_index >= 0 else group[link.parent]
    return group
