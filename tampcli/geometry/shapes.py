"""FCL geometry for robot links and scene bodies, with bounding spheres.

Meshes become their convex hull (as PyBullet treats a URDF or GEOM_MESH
collision mesh), so FCL and PyBullet see the same solids and signed
distances are defined (GJK/EPA need convex shapes). PyBullet rounds every
hull it builds by a collision margin of HULL_MARGIN (its URDF loader's and
createCollisionShape's default; primitives keep theirs inside): its
distances are those of the hull grown by a ball of that radius, measured
1.0 mm shorter per hull (a Panda finger against a box). A hull's `margin`
says so, and signed distances (narrow.rounded) subtract it: a convex solid
grown by a ball of radius r is exactly r closer to everything, penetrating
or not, with the same normal.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import fcl
import numpy as np

from tampcli.errors import SceneError
from tampcli.geometry.meshes import read_mesh_parts

HULL_MARGIN = 1e-3  # m: PyBullet's collision margin on a convex hull (btConvexHullShape)


@dataclass(frozen=True)
class Shape:
    """One convex solid rigidly attached to an owner frame."""

    geometry: object  # an fcl.CollisionGeometry
    local: np.ndarray  # 4x4 pose in the owner's frame
    center: np.ndarray  # (3,) bounding-sphere centre in the owner's frame
    radius: float  # bounding-sphere radius
    kind: str = "convex"  # box | cylinder | sphere | capsule | convex
    size: tuple[float, ...] = ()  # box extents; (radius, height); (radius,)
    vertices: np.ndarray | None = None  # convex only, in the shape's own frame
    margin: float = 0.0  # m: the solid is this shape grown by a ball of this radius

    def support(self, direction_local: np.ndarray) -> float:
        """max over the core (the solid less its margin) of direction . x, in the
        shape's own frame."""
        u = direction_local
        if self.kind == "box":
            return 0.5 * float(np.abs(u) @ np.asarray(self.size))
        if self.kind == "sphere":
            return self.size[0] * float(np.linalg.norm(u))
        if self.kind == "cylinder":
            r, h = self.size
            return r * float(np.hypot(u[0], u[1])) + 0.5 * h * abs(float(u[2]))
        if self.kind == "capsule":
            r, h = self.size
            return r * float(np.linalg.norm(u)) + 0.5 * h * abs(float(u[2]))
        return float(np.max(self.vertices @ u))

    def support_point(self, direction_local: np.ndarray) -> np.ndarray:
        """A point of the core maximizing direction . x (own frame)."""
        u = direction_local
        if self.kind == "box":
            return 0.5 * np.sign(u) * np.asarray(self.size)
        if self.kind == "sphere":
            return self.size[0] * u / max(np.linalg.norm(u), 1e-12)
        if self.kind in ("cylinder", "capsule"):
            r, h = self.size
            radial = np.array([u[0], u[1], 0.0])
            norm = np.linalg.norm(radial)
            point = np.array([0.0, 0.0, 0.5 * h * np.sign(u[2])])
            if self.kind == "capsule":
                return point + r * u / max(np.linalg.norm(u), 1e-12)
            return point + (r * radial / norm if norm > 1e-12 else 0.0)
        return self.vertices[int(np.argmax(self.vertices @ u))]


def primitive(kind: str, size, local=None) -> Shape:
    """A box (full extents), cylinder (radius, height, along z) or sphere (radius,)."""
    local = np.eye(4) if local is None else np.asarray(local, dtype=float)
    if kind == "box":
        geom = fcl.Box(*size)
        radius = 0.5 * float(np.linalg.norm(size))
    elif kind == "cylinder":
        r, h = size
        geom = fcl.Cylinder(r, h)
        radius = float(np.hypot(r, h / 2))
    elif kind == "sphere":
        geom = fcl.Sphere(size[0])
        radius = float(size[0])
    elif kind == "capsule":
        r, h = size
        geom = fcl.Capsule(r, h)
        radius = r + h / 2
    else:
        raise ValueError(kind)
    vertices = None
    if kind == "box":
        half = 0.5 * np.asarray(size, dtype=float)
        vertices = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * half
    return Shape(geom, local, local[:3, 3].copy(), radius, kind, tuple(float(v) for v in size),
                 vertices)


def mesh_hulls(path: str, scale=(1.0, 1.0, 1.0), local=None) -> list[Shape]:
    """The convex parts of a mesh file (see meshes.py), scaled, each as an fcl.Convex."""
    local = np.eye(4) if local is None else np.asarray(local, dtype=float)
    shapes = []
    for vertices, faces in _hulls(path, tuple(float(s) for s in scale)):
        geom = fcl.Convex(vertices, len(faces) // 4, faces)
        lo, hi = vertices.min(axis=0), vertices.max(axis=0)
        mid = 0.5 * (lo + hi)
        radius = float(np.max(np.linalg.norm(vertices - mid, axis=1)))
        shapes.append(Shape(geom, local, local[:3, :3] @ mid + local[:3, 3],
                            radius + HULL_MARGIN, "convex", (), vertices, HULL_MARGIN))
    return shapes


@functools.lru_cache(maxsize=64)
def _hulls(path: str, scale: tuple[float, float, float]):
    """Per part: hull vertices and FCL face list [3, i, j, k, ...], faces wound outward.

    Cached by file and scale: the Panda's meshes are read once per process
    (the arrays are read-only).
    """
    return tuple(_hull(points * np.array(scale), path) for points in read_mesh_parts(path))


def _hull(points: np.ndarray, path: str):
    # scipy.spatial takes about a second to import: only scenes with meshes pay it.
    from scipy.spatial import ConvexHull

    try:
        hull = ConvexHull(points)
    except Exception as e:  # noqa: BLE001 - scipy raises QhullError for flat or tiny meshes
        raise SceneError(f"mesh has no volume, cannot build its convex hull: {e}".split("\n")[0],
                         path=path) from None
    used = np.unique(hull.simplices)
    remap = -np.ones(len(points), dtype=int)
    remap[used] = np.arange(len(used))
    vertices = points[used]
    simplices = hull.simplices.copy()
    a, b, c = (points[simplices[:, k]] for k in range(3))
    inward = np.einsum("ij,ij->i", np.cross(b - a, c - a), hull.equations[:, :3]) < 0
    simplices[inward] = simplices[inward][:, [0, 2, 1]]
    faces = np.column_stack([np.full(len(simplices), 3), remap[simplices]]).ravel()
    face_array = faces.astype(np.int64)
    vertices.flags.writeable = False
    face_array.flags.writeable = False
    return vertices, face_array


def fcl_transform(t: np.ndarray) -> fcl.Transform:
    return fcl.Transform(t[:3, :3], t[:3, 3])
