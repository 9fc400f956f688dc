"""Planar footprints: each body and the robot seen from above as a centrally symmetric polygon.

Collision avoidance between two footprints A (centred at p) and B (at q) is the
separating-axis test on their Minkowski sum: the interiors are disjoint iff for
some edge normal n of A or B, n . (p - q) >= h_A(n) + h_B(n) (h: support
function). Boxes are exact; a disk (the robot, a cylinder) is a regular
polygon, circumscribed ("outer": the polygon contains the disk, so a separated
pair is truly separated) or inscribed ("inner": a relaxation of the disk).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tampcli.errors import InputError
from tampcli.geometry import transforms

TILT = 1e-6  # |roll|, |pitch| above this: the body is not upright


@dataclass(frozen=True)
class Footprint:
    """A body's outline from above, relative to its centre, and its height span."""

    name: str
    vertices: tuple[tuple[float, float], ...]  # counter-clockwise, centrally symmetric
    z_low: float
    z_high: float
    extent: tuple[float, float]  # half extents of the true outline's bounding box (x, y)
    reach: float  # the largest horizontal half extent in the body's frame (suction reach)

    def normals(self) -> list[np.ndarray]:
        v = np.asarray(self.vertices)
        edges = np.roll(v, -1, axis=0) - v
        return [np.array([e[1], -e[0]]) / math.hypot(*e) for e in edges]

    def support(self, n: np.ndarray) -> float:
        return float(np.max(np.asarray(self.vertices) @ n))


def disk(name: str, radius: float, z_low: float, z_high: float, sides: int,
         outer: bool) -> Footprint:
    """A regular polygon for a disk whose edge normals point along angles 2 pi i / sides."""
    rho = radius / math.cos(math.pi / sides) if outer else radius
    angles = [(i + 0.5) * 2 * math.pi / sides for i in range(sides)]
    return Footprint(name, tuple((rho * math.cos(a), rho * math.sin(a)) for a in angles),
                     z_low, z_high, (radius, radius), radius)


def box(name: str, size, yaw: float, z_low: float, z_high: float) -> Footprint:
    hx, hy = 0.5 * size[0], 0.5 * size[1]
    c, s = math.cos(yaw), math.sin(yaw)
    corners = [(a * hx, b * hy) for a, b in ((1, 1), (-1, 1), (-1, -1), (1, -1))]
    verts = tuple((c * x - s * y, s * x + c * y) for x, y in corners)
    extent = (abs(c) * hx + abs(s) * hy, abs(s) * hx + abs(c) * hy)
    return Footprint(name, verts, z_low, z_high, extent, max(hx, hy))


def separating_faces(a: Footprint, b: Footprint) -> list[tuple[np.ndarray, float]]:
    """(n, offset): the faces of A + B; A at p and B at q are apart iff n.(p - q) >= offset
    for one of them."""
    faces: list[tuple[np.ndarray, float]] = []
    for n in a.normals() + b.normals():
        if any(float(n @ m) > 1 - 1e-9 for m, _ in faces):
            continue
        faces.append((n, a.support(n) + b.support(n)))
    return faces


def overlaps_in_height(a: Footprint, b: Footprint, tolerance: float = 1e-3) -> bool:
    """Whether two bodies' height spans overlap by more than `tolerance` (touching is not a
    collision: it is what the planar robot and its load do with the surface they slide on)."""
    return min(a.z_high, b.z_high) - max(a.z_low, b.z_low) > tolerance


def body_footprint(body, scene_path: str | None, sides: int, outer: bool) -> Footprint:
    """A scene body's footprint; a shape or pose the MINLP cannot draw is refused."""
    if body.shape not in ("box", "cylinder"):
        raise InputError(f"the MINLP handles box and cylinder bodies only; {body.name!r} is a "
                         f"{body.shape}", scene_path, body.line, key="objects.shape")
    matrix = transforms.pose_from_xyzquat(body.pose)
    if abs(matrix[2, 2]) < 1 - TILT:
        raise InputError(f"the MINLP handles upright bodies only; {body.name!r} is tilted",
                         scene_path, body.line, key="objects.pose")
    z = float(matrix[2, 3])
    if body.shape == "box":
        half_z = 0.5 * body.size[2]
        yaw = math.atan2(matrix[1, 0], matrix[0, 0])
        return box(body.name, body.size, yaw, z - half_z, z + half_z)
    radius, height = body.size
    return disk(body.name, radius, z - 0.5 * height, z + 0.5 * height, sides, outer)


def robot_footprint(scene, sides: int, outer: bool) -> Footprint:
    """The planar robot's cylinder; any other robot is refused."""
    spec = scene.robot
    if spec.model != "planar":
        raise InputError(f"the MINLP handles the planar robot only (model = \"planar\"), "
                         f"found model = {spec.model!r}", scene.path, spec.line,
                         key="robot.model")
    z = float(spec.base_pose[2, 3])
    return disk("robot", spec.radius, z - 0.5 * spec.height, z + 0.5 * spec.height, sides,
                outer)
