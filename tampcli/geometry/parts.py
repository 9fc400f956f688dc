"""The collision parts of a World: shapes on robot links and on scene bodies.

Also the static facts the checker derives from them once: rigid groups of
links, the robot's support, and the self-collision pairs worth checking.
"""

from __future__ import annotations

from dataclasses import dataclass

import fcl
import numpy as np

from tampcli.errors import SceneError
from tampcli.geometry import obb
from tampcli.geometry.scene_check import body_error, entry_error
from tampcli.geometry.shapes import Shape, fcl_transform, mesh_hulls, primitive

SUPPORT_TOLERANCE = 0.005  # m


@dataclass
class Part:
    """One collision object: a shape on a robot link (link >= 0), a body, or the held object."""

    owner: str  # "link:NAME", "body:NAME" or "held:NAME"
    shape: Shape
    obj: fcl.CollisionObject
    link: int = -1  # chain index for robot shapes
    body: str | None = None
    identity_local: bool = False  # the shape frame is the owner's frame (skip a product)
    obb_center: np.ndarray = None  # (3,) a tight oriented box around the solid, owner frame
    obb_rot: np.ndarray = None  # (3, 3) its axes (columns)
    obb_half: np.ndarray = None  # (3,) its half extents
    hull: np.ndarray = None  # (V, 3) owner-frame points whose hull contains the solid

    def __post_init__(self):
        self.identity_local = bool(np.allclose(self.shape.local, np.eye(4), atol=1e-12))
        self.obb_center, self.obb_rot, self.obb_half = obb.fit(self.shape)
        self.hull = obb.hull_points(self.shape, self.obb_center, self.obb_rot, self.obb_half)


def fcl_object(shape: Shape) -> fcl.CollisionObject:
    return fcl.CollisionObject(shape.geometry, fcl_transform(shape.local))


def robot_parts(world) -> list[Part]:
    parts = []
    for i, link in enumerate(world.chain.links):
        try:
            shapes = world.robot_link_shapes(i)
        except SceneError as e:  # a collision mesh of the robot's URDF without volume
            if e.path == world.scene.path:
                raise
            key = "urdf" if world.scene.robot.urdf else "model"
            raise entry_error(world.scene, f"link {link.name!r}: {e.location()}: {e.message}",
                              "robot", 0, key) from None
        for shape in shapes:
            parts.append(Part(f"link:{link.name}", shape, fcl_object(shape), i))
    return parts


def body_shapes(world, body) -> list[Shape]:
    """Shapes of a scene body in its own frame (primitives exact, meshes as hulls).

    A mesh that cannot become hulls (no volume, unreadable) is a SceneError
    at the body's `mesh` or `urdf` key of the scene file.
    """
    if body.shape in ("box", "cylinder", "sphere"):
        return [primitive(body.shape, body.size)]
    try:
        if body.shape == "mesh":
            return mesh_hulls(body.mesh, body.scale)
        return world.body_collision_shapes(body.name)
    except SceneError as e:
        if e.path == world.scene.path:
            raise
        raise body_error(world.scene, body, body.shape, f"{e.location()}: {e.message}") from None


def rigid_groups(chain) -> list[int]:
    """Per link: the index of the link whose joint (a variable) last moves it; 0 = base."""
    group = [0] * len(chain.links)
    for i, link in enumerate(chain.links):
        if i > 0:
            group[i] = i if link.q_index >= 0 else group[link.parent]
    return group


def find_support(world, fixed: set[str]) -> frozenset[str]:
    """Fixed bodies the robot stands (planar: slides) on: top face at its base height."""
    spec = world.scene.robot
    base = spec.base_pose[:3, 3]
    bottom = base[2] - (spec.height / 2 if spec.model == "planar" else 0.0)
    found = set()
    for name in fixed:
        lo, hi = world.aabb(name)
        if abs(hi[2] - bottom) > SUPPORT_TOLERANCE:
            continue
        inside = lo[0] <= base[0] <= hi[0] and lo[1] <= base[1] <= hi[1]
        if inside or spec.model == "planar":
            found.add(name)
    return frozenset(found)
