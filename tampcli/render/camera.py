"""Where the camera stands: from `--camera`, the scene's `[camera]`, or framed
automatically around the scene's bounding box."""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import dataclass

import numpy as np

from tampcli.errors import UsageError

# Between two camera fields: a blank, ";" or "," that a field name follows.
_FIELD_SEPARATOR = re.compile(r"\s*[\s;,]\s*(?=[A-Za-z_]\w*\s*=)")

# Looking from the front-right and above, like the SPEC's example camera.
_AUTO_DIRECTION = np.array([1.0, 0.75, 0.7])


@dataclass(frozen=True)
class Camera:
    """A pinhole camera: positions in metres, `fov` the vertical field of view in degrees."""

    eye: tuple[float, float, float]
    target: tuple[float, float, float]
    up: tuple[float, float, float] = (0.0, 0.0, 1.0)
    fov: float = 50.0

    def __post_init__(self):
        for name in ("eye", "target", "up"):
            value = getattr(self, name)
            if len(value) != 3 or not all(math.isfinite(v) for v in value):
                raise UsageError(f"{name} needs 3 finite numbers", key="--camera")
        _check_fov(self.fov)
        view = np.subtract(self.target, self.eye)
        if np.linalg.norm(view) < 1e-9:
            raise UsageError("eye and target coincide", key="--camera")
        if np.linalg.norm(np.cross(view, self.up)) < 1e-9 * np.linalg.norm(view):
            raise UsageError("up is parallel to the viewing direction", key="--camera")


def parse_camera(specs: list[str] | str) -> dict:
    """`eye=x,y,z target=x,y,z [up=x,y,z] [fov=deg]` -> the given fields (a dict).

    `specs` is one string or several (`--camera` may be repeated; a later field
    wins); fields are separated by spaces, semicolons, or a comma before the
    next name (`eye=1,2,3,target=0,0,0`). Fields left out come from the scene
    or from automatic framing, so a user may move only the eye.
    """
    if isinstance(specs, str):
        specs = [specs]
    tokens = [t for spec in specs for t in _FIELD_SEPARATOR.split(spec.strip()) if t]
    fields: dict = {}
    for token in tokens:
        key, sep, value = token.partition("=")
        key = key.strip().lower()
        if not sep or key not in ("eye", "target", "up", "fov"):
            raise UsageError(f"expected eye=x,y,z target=x,y,z up=x,y,z or fov=degrees, "
                             f"got {token!r}", key="--camera")
        try:
            numbers = tuple(float(v) for v in value.split(","))
        except ValueError:
            raise UsageError(f"{key}: not a list of numbers: {value!r}", key="--camera") from None
        if key == "fov":
            if len(numbers) != 1:
                raise UsageError("fov takes one number (degrees)", key="--camera")
            # now, not in Camera: automatic framing divides by tan(fov / 2) first
            fields[key] = _check_fov(numbers[0])
        else:
            if len(numbers) != 3:
                raise UsageError(f"{key} needs 3 numbers x,y,z, got {len(numbers)}",
                                 key="--camera")
            fields[key] = numbers
    return fields


def _check_fov(fov: float) -> float:
    if not 1.0 <= fov <= 170.0:
        raise UsageError(f"fov must be in [1, 170] degrees, got {fov}", key="--camera")
    return fov


def box_corners(lo, hi) -> np.ndarray:
    """(8, 3) corners of the axis-aligned box [lo, hi]."""
    return np.array(list(itertools.product(*zip(lo, hi, strict=True))), dtype=float)


def auto_camera(points, fov: float = 50.0, aspect: float = 4 / 3,
                margin: float = 1.05, reserve_bottom: float = 0.0) -> Camera:
    """The closest camera looking along a fixed direction (from the front-right,
    above) that sees all `points` (k, 3), with `margin` around them, above the
    bottom `reserve_bottom` fraction of the image (where the caption goes).

    A point p is inside the view of an eye e iff it is on the inner side of
    the four planes of the view's sides, each linear in e: n . e >= n . p.
    Each pair (left/right, top/bottom) fixes how far sideways the eye sits
    and how far forward it may come; the eye takes the smaller of the two
    forward limits, so one pair of sides touches the points and the other
    leaves room. No iteration, so no instability for elongated scenes.
    """
    if not 0.0 <= reserve_bottom < 0.5:
        raise ValueError(f"reserve_bottom must be in [0, 0.5), got {reserve_bottom}")
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    back = _AUTO_DIRECTION / np.linalg.norm(_AUTO_DIRECTION)
    forward = -back
    right = np.cross(forward, (0.0, 0.0, 1.0))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    tan_v = math.tan(math.radians(fov) / 2.0) / margin
    tan_h = tan_v * aspect
    tan_b = tan_v * (1.0 - 2.0 * reserve_bottom)  # the usable image's bottom edge
    # m = max over points of n . p for the side planes' normals n = +-axis - tan * forward
    m_right, m_left = (float(np.max(points @ (s * right - tan_h * forward))) for s in (1, -1))
    m_top = float(np.max(points @ (up - tan_v * forward)))
    m_bottom = float(np.max(points @ (-up - tan_b * forward)))
    a = (m_right - m_left) / 2.0
    # top and bottom both touch: b - tan_v c = m_top and -b - tan_b c = m_bottom
    b = (m_top * tan_b - m_bottom * tan_v) / (tan_b + tan_v)
    c = min(-(m_right + m_left) / (2.0 * tan_h), (b - m_top) / tan_v)
    eye = a * right + b * up + c * forward
    depth = max(float(np.mean((points - eye) @ forward)), 0.1)
    target = eye + depth * forward
    return Camera(tuple(float(v) for v in eye), tuple(float(v) for v in target), fov=fov)


def choose_camera(given: dict | None, scene_camera, points, aspect: float,
                  reserve_bottom: float = 0.0) -> Camera:
    """`--camera` fields over the scene's `[camera]` over automatic framing."""
    if given and "fov" in given:
        _check_fov(given["fov"])
    base = None
    if scene_camera is not None:
        base = _from_scene(scene_camera)
    if base is None:
        base = auto_camera(points, fov=(given or {}).get("fov", 50.0), aspect=aspect,
                           reserve_bottom=reserve_bottom)
    fields = {"eye": base.eye, "target": base.target, "up": base.up, "fov": base.fov}
    fields.update(given or {})
    return Camera(**fields)


def _from_scene(scene_camera) -> Camera | None:
    """The scene's `[camera]` as a Camera, whatever shape the scene loader gives it."""
    if isinstance(scene_camera, Camera):
        return scene_camera
    get = scene_camera.get if isinstance(scene_camera, dict) else (
        lambda k, d=None: getattr(scene_camera, k, d))
    eye, target = get("eye"), get("target")
    if eye is None or target is None:
        return None
    up = get("up", None)
    fov = get("fov", None)
    return Camera(tuple(float(v) for v in eye), tuple(float(v) for v in target),
                  tuple(float(v) for v in up) if up is not None else (0.0, 0.0, 1.0),
                  float(fov) if fov is not None else 50.0)
