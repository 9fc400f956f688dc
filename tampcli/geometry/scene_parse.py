"""scene.toml text -> Scene: typed reading of each table, every error located at its key."""

from __future__ import annotations

import difflib
import math
from pathlib import Path

import numpy as np

from tampcli.errors import SceneError, source_line_at
from tampcli.geometry import transforms
from tampcli.geometry.arms import ARMS, Fingers
from tampcli.geometry.model import (
    COLORS,
    DEFAULT_COLOR,
    ROBOT_MODELS,
    SHAPES,
    Body,
    Camera,
    Region,
    RobotSpec,
    Scene,
)
from tampcli.geometry.region_check import is_upright, region_overhang
from tampcli.geometry.tomlsrc import TomlSource

_ROBOT_KEYS = ("model", "base", "start", "radius", "height", "urdf", "tool_link", "tool_offset",
               "joints", "fingers", "package_paths")
_URDF_KEYS = ("urdf", "tool_link", "tool_offset", "joints", "fingers", "package_paths")
_FINGER_KEYS = ("joints", "open", "closed")
_OBJECT_KEYS = ("name", "shape", "size", "pose", "fixed", "color", "mesh", "urdf", "scale",
                "mass")
_REGION_KEYS = ("name", "on", "center", "size", "color")
_CAMERA_KEYS = ("eye", "target", "up", "fov")
_TOP_KEYS = ("robot", "objects", "regions", "camera")


def build_scene(src: TomlSource) -> Scene:
    data = src.data
    for key in data:
        if key not in _TOP_KEYS:
            raise src.error(f"unknown key; expected one of {', '.join(_TOP_KEYS)}", key, 0,
                            name=key)
    if "robot" not in data:
        raise SceneError("missing [robot] table", path=src.path, line=1, key="robot",
                         source_line=source_line_at(src.text, 1))
    if not isinstance(data["robot"], dict):
        raise src.error("must be a table [robot]", None, 0, "robot", name="robot")
    robot = _robot(src, data["robot"])
    objects = data.get("objects", [])
    if not isinstance(objects, list) or not all(isinstance(o, dict) for o in objects):
        raise src.error("must be an array of tables [[objects]]", None, 0, "objects",
                        name="objects")
    bodies = tuple(_body(src, i, o) for i, o in enumerate(objects))
    seen: dict[str, int] = {}
    for i, b in enumerate(bodies):
        if b.name in seen:
            raise src.error(f"duplicate object name {b.name!r}", "objects", i, "name",
                            "objects.name")
        seen[b.name] = i
    regions_data = data.get("regions", [])
    if not isinstance(regions_data, list) or not all(isinstance(o, dict) for o in regions_data):
        raise src.error("must be an array of tables [[regions]]", None, 0, "regions",
                        name="regions")
    regions = tuple(_region(src, i, r) for i, r in enumerate(regions_data))
    for i, r in enumerate(regions):
        if r.name in seen:
            raise src.error(f"{r.name!r} is both an object and a region", "regions", i, "name",
                            "regions.name")
        seen[r.name] = i
        if r.on not in {b.name for b in bodies}:
            near = difflib.get_close_matches(r.on, [b.name for b in bodies], n=1)
            hint = f" (did you mean {near[0]!r}?)" if near else \
                f" (its objects: {', '.join(b.name for b in bodies)})"
            raise src.error(f"region {r.name!r} is on {r.on!r}, which is no object of the "
                            f"scene{hint}", "regions", i, "on", "regions.on")
        support = next(b for b in bodies if b.name == r.on)
        if support.shape not in ("box", "cylinder"):
            raise src.error(f"region {r.name!r} must lie on a box or cylinder, {r.on!r} is a "
                            f"{support.shape}", "regions", i, "on", "regions.on")
        if not is_upright(support):
            raise src.error(f"region {r.name!r} is on {r.on!r}, which is not upright: its top "
                            "face must be horizontal to hold a region", "regions", i, "on",
                            f"regions.{r.name}")
        off = region_overhang(r, support)
        if off is not None:
            (x, y) = off[1]
            raise src.error(f"region {r.name!r} is not inside the top face of {r.on!r}: its "
                            f"corner ({x:.3f}, {y:.3f}) lies {off[0] * 100:.1f} cm off it "
                            "(expected a rectangle within the support's top face)",
                            "regions", i, "center", f"regions.{r.name}")
    camera = _camera(src, data["camera"]) if "camera" in data else None
    return Scene(src.path, robot, bodies, regions, camera)


class _Reader:
    """Typed access to one table of the file, every error located at its key."""

    def __init__(self, src: TomlSource, table: str, index: int, data: dict, allowed):
        self.src, self.table, self.index, self.data = src, table, index, data
        if not isinstance(data, dict):
            raise src.error("must be a table", table, index, name=table)
        for key in data:
            if key not in allowed:
                raise self.error(f"unknown key; expected one of {', '.join(allowed)}", key)

    def error(self, message: str, key: str | None) -> SceneError:
        name = f"{self.table}.{key}" if key else self.table
        return self.src.error(message, self.table, self.index, key, name)

    def missing(self, key: str, what: str | None = None) -> SceneError:
        """A missing key: located at the entry's `name` line, else its header."""
        message = f"missing key {key!r}" + (f" ({what})" if what else "")
        name = f"{self.table}.{key}"
        anchor = "name" if "name" in self.data else None
        return self.src.error(message, self.table, self.index, anchor, name)

    def has(self, key: str) -> bool:
        return key in self.data

    def string(self, key: str, default=None, required=False, choices=None) -> str | None:
        if key not in self.data:
            if required:
                raise self.missing(key)
            return default
        value = self.data[key]
        if not isinstance(value, str) or not value:
            raise self.error(f"expected a non-empty string, got {_show(value)}", key)
        if choices is not None and value not in choices:
            raise self.error(f"unknown value {value!r}; expected one of {', '.join(choices)}", key)
        return value

    def boolean(self, key: str, default: bool) -> bool:
        value = self.data.get(key, default)
        if not isinstance(value, bool):
            raise self.error(f"expected true or false, got {_show(value)}", key)
        return value

    def number(self, key: str, default: float | None = None, positive=False) -> float:
        if key not in self.data:
            if default is None:
                raise self.missing(key)
            return default
        value = self.data[key]
        if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
            raise self.error(f"expected a number, got {_show(value)}", key)
        if positive and value <= 0:
            raise self.error(f"must be positive, got {value}", key)
        return float(value)

    def numbers(self, key: str, lengths, what: str, positive=False, required=True):
        if key not in self.data:
            if required:
                raise self.missing(key, what)
            return None
        value = self.data[key]
        ok = (isinstance(value, list)
              and all(not isinstance(v, bool) and isinstance(v, int | float) for v in value)
              and all(math.isfinite(v) for v in value) and len(value) in lengths)
        if ok and positive:
            ok = all(v > 0 for v in value)
        if not ok:
            raise self.error(f"expected {what}, got {_show(value)}", key)
        return tuple(float(v) for v in value)

    def strings(self, key: str):
        if key not in self.data:
            return None
        value = self.data[key]
        if not isinstance(value, list) or not value or not all(
                isinstance(v, str) and v for v in value):
            raise self.error(f"expected a non-empty list of names, got {_show(value)}", key)
        return tuple(value)

    def pose(self, key: str, required=True):
        values = self.numbers(key, (3, 4, 6), "a pose [x, y, z], [x, y, z, yaw] or "
                              "[x, y, z, roll, pitch, yaw]", required=required)
        if values is None:
            return None
        return tuple(transforms.xyzquat_from_pose(transforms.pose_from_list(values)))

    def color(self, key: str, default):
        if key not in self.data:
            return default
        value = self.data[key]
        if isinstance(value, str):
            if value.lower() not in COLORS:
                raise self.error(f"unknown color {value!r}; expected one of "
                                 f"{', '.join(sorted(COLORS))} or [r, g, b, a]", key)
            return COLORS[value.lower()]
        rgba = self.numbers(key, (3, 4), "a color name or [r, g, b] / [r, g, b, a] in 0..1")
        if not all(0.0 <= v <= 1.0 for v in rgba):
            raise self.error(f"color components must lie in 0..1, got {_show(value)}", key)
        return rgba + (1.0,) if len(rgba) == 3 else rgba

    def path(self, key: str) -> str | None:
        value = self.string(key)
        if value is None:
            return None
        resolved = Path(self.src.path).parent / value
        if not resolved.is_file():
            raise self.error(f"file not found: {resolved}", key)
        return str(resolved)


def _show(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return repr(value)
    if isinstance(value, dict):
        return "a table"
    return str(value)


def _robot(src: TomlSource, data: dict) -> RobotSpec:
    r = _Reader(src, "robot", 0, data, _ROBOT_KEYS)
    model = r.string("model", default="urdf" if r.has("urdf") else "panda",
                     choices=ROBOT_MODELS)
    base = r.pose("base", required=False) or RobotSpec.base
    start = r.numbers("start", range(1, 64), "a list of joint values", required=False)
    radius = r.number("radius", 0.05, positive=True)
    height = r.number("height", 0.05, positive=True)
    if model == "urdf":
        if not r.has("urdf"):
            raise r.error("model \"urdf\" needs `urdf` (the file) and `tool_link` (the link "
                          "the tool is fixed to); see docs/robots.md", "model")
        if not r.has("tool_link"):
            raise r.error("a URDF robot needs `tool_link`: the link the tool is fixed to "
                          "(see docs/robots.md)", "urdf")
    else:
        for key in _URDF_KEYS:
            if r.has(key):
                raise r.error(f"only for model \"urdf\", not {model!r}", key)
    if model != "planar":
        for key in ("radius", "height"):
            if r.has(key):
                raise r.error(f"only for model \"planar\", not {model!r}", key)
    joints = r.strings("joints")
    if start is not None:
        known = {"planar": ("x", "y")}.get(model) or joints or (
            ARMS[model].joints if model in ARMS else None)
        if known is not None and len(start) != len(known):
            raise r.error(f"expected {len(known)} joint values for the {model} robot, "
                          f"got {len(start)}", "start")
    offset, frame = _tool_offset(r)
    return RobotSpec(model, base, start, radius, height, r.path("urdf"), r.string("tool_link"),
                     joints, offset, frame, _fingers(r), _folders(r, "package_paths"),
                     line=src.line("robot"))


def _tool_offset(r: _Reader):
    """(pose as xyz + quat, None) or (None, link name) or (None, None)."""
    if not r.has("tool_offset"):
        return None, None
    value = r.data["tool_offset"]
    if isinstance(value, str):
        return None, r.string("tool_offset")
    values = r.numbers("tool_offset", (3, 4, 6, 7), "a pose [x, y, z], [x, y, z, yaw], "
                       "[x, y, z, roll, pitch, yaw] or [x, y, z, qx, qy, qz, qw], or the name "
                       "of a link")
    if len(values) == 7 and np.linalg.norm(values[3:]) < 1e-9:
        raise r.error("the quaternion [qx, qy, qz, qw] must not be zero", "tool_offset")
    return tuple(transforms.xyzquat_from_pose(transforms.pose_from_list(values))), None


def _fingers(r: _Reader) -> Fingers | None:
    if not r.has("fingers"):
        return None
    data = r.data["fingers"]
    what = "a table { joints = [names], open = value(s), closed = value(s) }"
    if not isinstance(data, dict):
        raise r.error(f"expected {what}, got {_show(data)}", "fingers")
    for key in data:
        if key not in _FINGER_KEYS:
            raise r.error(f"unknown key {key!r}; expected one of {', '.join(_FINGER_KEYS)}",
                          "fingers")
    joints = data.get("joints")
    if not isinstance(joints, list) or not joints or not all(
            isinstance(j, str) and j for j in joints):
        raise r.error(f"fingers.joints: expected a non-empty list of joint names, got "
                      f"{_show(joints)}", "fingers")
    values = {}
    for key in ("open", "closed"):
        value = data.get(key)
        if isinstance(value, int | float) and not isinstance(value, bool):
            value = [value] * len(joints)
        ok = (isinstance(value, list) and len(value) == len(joints)
              and all(isinstance(v, int | float) and not isinstance(v, bool)
                      and math.isfinite(v) for v in value))
        if not ok:
            raise r.error(f"fingers.{key}: expected a joint value, or one per finger joint "
                          f"({len(joints)}), got {_show(value)}", "fingers")
        values[key] = tuple(float(v) for v in value)
    if values["open"] == values["closed"]:
        raise r.error("fingers: `open` and `closed` are the same values", "fingers")
    return Fingers(tuple(joints), values["open"], values["closed"])


def _folders(r: _Reader, key: str) -> tuple[str, ...]:
    names = r.strings(key) or ()
    out = []
    for name in names:
        folder = Path(r.src.path).parent / name
        if not folder.is_dir():
            raise r.error(f"no such folder: {folder}", key)
        out.append(str(folder))
    return tuple(out)


def _body(src: TomlSource, index: int, data: dict) -> Body:
    r = _Reader(src, "objects", index, data, _OBJECT_KEYS)
    name = r.string("name", required=True).lower()
    shape = r.string("shape", required=True, choices=SHAPES)
    size: tuple[float, ...] = ()
    mesh = urdf = None
    if shape == "box":
        size = r.numbers("size", (3,), "3 positive numbers [x, y, z] for a box", positive=True)
    elif shape == "cylinder":
        size = r.numbers("size", (2,), "2 positive numbers [radius, height] for a cylinder",
                         positive=True)
    elif shape == "sphere":
        size = r.numbers("size", (1,), "1 positive number [radius] for a sphere", positive=True)
    elif shape == "mesh":
        mesh = r.path("mesh")
        if mesh is None:
            raise r.error("a mesh object needs `mesh = \"file.obj\"`", "shape")
        if not mesh.lower().endswith((".obj", ".stl")):
            raise r.error("a mesh must be a Wavefront .obj or an .stl file", "mesh")
    else:
        urdf = r.path("urdf")
        if urdf is None:
            raise r.error("a urdf object needs `urdf = \"file.urdf\"`", "shape")
    if shape in ("mesh", "urdf"):
        if r.has("size"):
            raise r.error(f"a {shape} takes its size from its file; use `scale`", "size")
    else:
        for key in ("mesh", "urdf", "scale"):
            if r.has(key):
                raise r.error(f"only for shape \"mesh\" or \"urdf\", not {shape!r}", key)
    scale = (1.0, 1.0, 1.0)
    if r.has("scale"):
        if isinstance(data["scale"], int | float) and not isinstance(data["scale"], bool):
            scale = (r.number("scale", positive=True),) * 3
        else:
            scale = r.numbers("scale", (3,), "a positive number or 3 of them", positive=True)
        if shape == "urdf" and len(set(scale)) != 1:
            raise r.error("a urdf object scales uniformly: give one number", "scale")
    mass = r.number("mass", None, positive=True) if r.has("mass") else None
    fixed = r.boolean("fixed", False)
    if mass is not None and fixed:
        raise r.error("a fixed object does not move: `mass` is only for movable ones", "mass")
    body = Body(name=name, shape=shape, size=size, pose=r.pose("pose"),
                fixed=fixed, color=r.color("color", DEFAULT_COLOR),
                mesh=mesh, urdf=urdf, scale=scale, mass=mass,
                line=src.line("objects", index, "name"))
    if not fixed and not is_upright(body):
        # Grips are built in the body's frame and every placement is upright: a body
        # lying on its side would be gripped through itself, or refused as too wide
        # (a false proof of infeasibility).
        tilt = math.degrees(math.acos(min(1.0, max(-1.0, float(body.matrix[2, 2])))))
        raise r.error(f"a movable object must start upright (its pose turned about z "
                      f"only): {name!r} is tilted {tilt:.1f} deg; a fixed one may lie any "
                      "way", "pose")
    return body


def _region(src: TomlSource, index: int, data: dict) -> Region:
    r = _Reader(src, "regions", index, data, _REGION_KEYS)
    return Region(name=r.string("name", required=True).lower(),
                  on=r.string("on", required=True).lower(),
                  center=r.numbers("center", (2,), "the centre [x, y] of the region"),
                  size=r.numbers("size", (2,), "2 positive numbers [x, y]", positive=True),
                  color=r.color("color", Region.color),
                  line=src.line("regions", index, "name"))


def _camera(src: TomlSource, data: dict) -> Camera:
    r = _Reader(src, "camera", 0, data, _CAMERA_KEYS)
    eye = r.numbers("eye", (3,), "a point [x, y, z]")
    target = r.numbers("target", (3,), "a point [x, y, z]")
    up = r.numbers("up", (3,), "a direction [x, y, z]", required=False) or (0.0, 0.0, 1.0)
    fov = r.number("fov", 50.0, positive=True)
    if fov >= 180:
        raise r.error(f"field of view in degrees must be below 180, got {fov}", "fov")
    if np.linalg.norm(np.subtract(eye, target)) < 1e-6:
        raise r.error("eye and target coincide", "target")
    if np.linalg.norm(up) < 1e-9:
        raise r.error("up must not be zero", "up")
    return Camera(eye, target, up, fov)
