"""What the optimizer needs to know of a scene body: extents, footprint, resting pose.

Every movable object is upright whenever it rests (grasps are top grasps, pushes
keep it on its support), so a resting pose is (x, y, z, yaw) and the height at
which an object rests on a support follows from the stack below it alone.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize.units import cm

# Resting contact tolerance (docs/formats.md, "Resting contact"): bottom to top face.
REST_TOLERANCE = 0.005
# How far apart `verify` still calls a tool and the object it grasps or pushes touching (m).
TOUCH_TOLERANCE = 2e-3
# kg/m^3: a body without a `mass` in the scene weighs its volume times this (stability.py)
DENSITY = 1000.0


@dataclass(frozen=True)
class BodyInfo:
    name: str
    shape: str
    half: tuple[float, float, float]  # half extents in the body frame (x, y, z)
    fixed: bool
    pose: tuple[float, float, float, float]  # start (x, y, z, yaw)
    upright: bool  # the start pose has its z axis vertical
    mass: float = 1.0  # kg: the scene's `mass`, else DENSITY x volume
    # The shape is the body's (box, cylinder, sphere), not a bounding box of a mesh or
    # URDF: only then does a width or footprint test prove anything.
    exact: bool = True

    @property
    def disk(self) -> bool:
        """Footprint is a disk (cylinder, sphere) rather than a rectangle."""
        return self.shape in ("cylinder", "sphere")

    @property
    def radius(self) -> float:
        """Radius of the circle around the footprint (conservative for overlap tests)."""
        return self.half[0] if self.disk else math.hypot(self.half[0], self.half[1])

    @property
    def sphere(self) -> float:
        """Radius of the sphere about the centre that holds the whole body (its half
        diagonal): a tool holding the body is within it of the centre."""
        return math.sqrt(self.half[0] ** 2 + self.half[1] ** 2 + self.half[2] ** 2)

    @property
    def top(self) -> float:
        return self.pose[2] + self.half[2]

    @property
    def bottom(self) -> float:
        return self.pose[2] - self.half[2]


def body_info(body, world=None) -> BodyInfo:
    """Extents from the shape's size; meshes and URDFs from their PyBullet AABB."""
    m = body.matrix
    yaw = transforms.yaw_of(m)
    upright = bool(m[2, 2] > 1.0 - 1e-6)
    if body.shape == "box":
        half = tuple(0.5 * s for s in body.size)
    elif body.shape == "cylinder":
        half = (body.size[0], body.size[0], 0.5 * body.size[1])
    elif body.shape == "sphere":
        half = (body.size[0],) * 3
    else:
        lo, hi = _aabb(world, body.name)
        half = tuple(float(h) for h in 0.5 * (hi - lo))
        centre = 0.5 * (hi + lo)
        return BodyInfo(body.name, "box", half, body.fixed,
                        (float(centre[0]), float(centre[1]), float(centre[2]), 0.0), True,
                        _mass(body, "box", half), exact=False)
    if not upright:
        # A tilted body: treat it by its world AABB (only obstacles are tilted sensibly).
        corners = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
        world_pts = corners * np.array(half) @ m[:3, :3].T
        half = tuple(np.max(np.abs(world_pts), axis=0))
        yaw = 0.0
    p = m[:3, 3]
    half = tuple(float(h) for h in half)
    return BodyInfo(body.name, body.shape, half, body.fixed,
                    (float(p[0]), float(p[1]), float(p[2]), float(yaw)), upright,
                    _mass(body, body.shape, half))


def _mass(body, shape: str, half) -> float:
    """The scene's mass when it gives one (a Body may carry `mass`), else uniform density."""
    given = getattr(body, "mass", None)
    if given is not None:
        return float(given)
    if shape == "cylinder":
        volume = math.pi * half[0] ** 2 * 2 * half[2]
    elif shape == "sphere":
        volume = 4.0 / 3.0 * math.pi * half[0] ** 3
    else:
        volume = 8 * half[0] * half[1] * half[2]
    return DENSITY * volume


def _aabb(world, name):
    if world is None:
        raise ValueError(f"body {name!r}: its extent needs the World (mesh or URDF)")
    return world.aabb(name)


def pose_matrix(x: float, y: float, z: float, yaw: float) -> np.ndarray:
    return transforms.pose(transforms.rot_z(yaw), (x, y, z))


def start_support(info: BodyInfo, infos: dict[str, BodyInfo]) -> str | None:
    """The body an object rests on at the start: top face at its bottom, under its centre."""
    best = None
    for other in infos.values():
        if other.name == info.name or abs(other.top - info.bottom) > REST_TOLERANCE:
            continue
        if inside_rect(info.pose[:2], other, 0.0):
            best = other.name
    return best


def inside_rect(xy, rect: BodyInfo, inset: float) -> bool:
    c, s = math.cos(rect.pose[3]), math.sin(rect.pose[3])
    d = np.asarray(xy, dtype=float) - np.asarray(rect.pose[:2])
    u, v = c * d[0] + s * d[1], -s * d[0] + c * d[1]
    if rect.disk:
        return math.hypot(u, v) <= rect.half[0] - inset
    return abs(u) <= rect.half[0] - inset and abs(v) <= rect.half[1] - inset


def region_misfit(obj: str, info: BodyInfo, region) -> str | None:
    """Why the object's footprint fits the region at no yaw (None: it fits at some);
    exact, so that a refusal is a proof: a 14 x 1 cm stick fits a 12 x 12 cm region
    turned 45 degrees, not square."""
    w, h = region.size
    a, b = 2 * info.half[0], 2 * info.half[1]
    if rectangle_fits(a, b, w, h):
        return None
    return (f"{obj} ({cm(a)} x {cm(b)} cm) does not fit region {region.name} "
            f"({cm(w)} x {cm(h)} cm) at any yaw")


def face_misfit(obj: str, info: BodyInfo, support: BodyInfo, overhang: float) -> str | None:
    """Why the object's footprint lies on the support's top face at no yaw and no
    offset, sticking out at most `overhang` (stability.footprint_on_face's rule); None:
    it does somewhere. Exact for boxes, cylinders and spheres, so a refusal is a proof
    (blind32 p04: an 8 x 12 cm case onto a 2.4 cm coin, drawn in 319 skeletons)."""
    if support.disk:
        reach = support.half[0] + overhang  # every corner (the rim) within this of the axis
        need = info.half[0] if info.disk else math.hypot(info.half[0], info.half[1])
        fits = need <= reach + 1e-12
    elif info.disk:
        fits = info.half[0] <= min(support.half[0], support.half[1]) + overhang + 1e-12
    else:
        fits = rectangle_fits(2 * info.half[0], 2 * info.half[1],
                              2 * (support.half[0] + overhang), 2 * (support.half[1] + overhang))
    if fits:
        return None

    def size(b: BodyInfo) -> str:
        return (f"{cm(2 * b.half[0])} cm across" if b.disk
                else f"{cm(2 * b.half[0])} x {cm(2 * b.half[1])} cm")

    return (f"{obj} ({size(info)}) does not fit on the top of {support.name} "
            f"({size(support)}) at any yaw")


def rectangle_fits(a: float, b: float, w: float, h: float, tol: float = 1e-12) -> bool:
    """Whether an a x b rectangle fits inside a w x h one at some turn theta in
    [0, pi/2]: a cos + b sin <= w and a sin + b cos <= h. With R = |(a, b)| and
    alpha = atan2(b, a) these read R cos(theta - alpha) <= w and R sin(theta + alpha)
    <= h; the set of feasible turns is a union of closed intervals, so it is empty
    unless one of its ends, theta = 0, pi/2 or a root of either, is feasible."""
    r, alpha = math.hypot(a, b), math.atan2(b, a)
    candidates = [0.0, 0.5 * math.pi]
    if w < r:
        candidates += [alpha + math.acos(w / r), alpha - math.acos(w / r)]
    if h < r:
        candidates += [math.asin(h / r) - alpha, math.pi - math.asin(h / r) - alpha]
    return any(a * math.cos(t) + b * math.sin(t) <= w + tol
               and a * math.sin(t) + b * math.cos(t) <= h + tol
               for t in candidates if -tol <= t <= 0.5 * math.pi + tol)
