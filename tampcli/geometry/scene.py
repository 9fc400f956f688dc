"""scene.toml -> Scene: the geometry of one problem (see SPEC.md, "scene.toml").

Obstacles: a body whose `name` is not an object (or constant) of the PDDL
problem is an obstacle. An obstacle must say `fixed = true`; it then takes
part in collisions but never in the symbolic plan. A body named in the PDDL
problem is movable unless it says `fixed = true` (a table, a shelf).

Every error is a SceneError located as `path:line: key: what is wrong`; the
line is the one of the offending key, or of its `[[objects]]` entry.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from tampcli.errors import SceneError, source_line_at
from tampcli.geometry import transforms
from tampcli.geometry.tomlsrc import TomlSource, read_toml
from tampcli.pddl import ast

SHAPES = ("box", "cylinder", "sphere", "mesh", "urdf")
ROBOT_MODELS = ("panda", "planar", "urdf")
PANDA_READY = (0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785)

COLORS = {
    "red": (0.85, 0.15, 0.15, 1.0),
    "green": (0.2, 0.7, 0.25, 1.0),
    "blue": (0.2, 0.35, 0.85, 1.0),
    "yellow": (0.95, 0.85, 0.2, 1.0),
    "orange": (0.95, 0.55, 0.1, 1.0),
    "purple": (0.55, 0.25, 0.7, 1.0),
    "cyan": (0.2, 0.8, 0.85, 1.0),
    "magenta": (0.85, 0.2, 0.75, 1.0),
    "pink": (0.95, 0.6, 0.7, 1.0),
    "brown": (0.55, 0.4, 0.3, 1.0),
    "wood": (0.65, 0.5, 0.35, 1.0),
    "white": (0.95, 0.95, 0.95, 1.0),
    "black": (0.1, 0.1, 0.1, 1.0),
    "gray": (0.5, 0.5, 0.5, 1.0),
    "grey": (0.5, 0.5, 0.5, 1.0),
}
DEFAULT_COLOR = (0.6, 0.6, 0.6, 1.0)

_ROBOT_KEYS = ("model", "base", "start", "radius", "height", "urdf", "tool_link", "joints")
_OBJECT_KEYS = ("name", "shape", "size", "pose", "fixed", "color", "mesh", "urdf", "scale")
_REGION_KEYS = ("name", "on", "center", "size", "color")
_CAMERA_KEYS = ("eye", "target", "up", "fov")
_TOP_KEYS = ("robot", "objects", "regions", "camera")


@dataclass(frozen=True)
class RobotSpec:
    """The robot: `panda`, `planar` (a disk moving in x, y) or any `urdf` arm."""

    model: str
    base: tuple[float, ...] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)  # xyz + quat (x, y, z, w)
    start: tuple[float, ...] | None = None
    radius: float = 0.05  # planar only (m)
    height: float = 0.05  # planar only (m)
    urdf: str | None = None  # resolved path (model "urdf")
    tool_link: str | None = None
    joints: tuple[str, ...] | None = None
    line: int | None = field(default=None, compare=False)

    @property
    def base_pose(self) -> np.ndarray:
        return transforms.pose_from_xyzquat(self.base)


@dataclass(frozen=True)
class Body:
    """A rigid body of the scene. `size`: box extents, cylinder (radius, height), sphere (radius,)."""

    name: str
    shape: str
    size: tuple[float, ...] = ()
    pose: tuple[float, ...] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)  # xyz + quat (x, y, z, w)
    fixed: bool = False
    color: tuple[float, float, float, float] = DEFAULT_COLOR
    mesh: str | None = None  # resolved path of an OBJ file
    urdf: str | None = None  # resolved path of a URDF file
    scale: tuple[float, float, float] = (1.0, 1.0, 1.0)
    obstacle: bool = False  # not named in the PDDL problem
    line: int | None = field(default=None, compare=False)

    @property
    def matrix(self) -> np.ndarray:
        """The start pose as a 4x4 matrix."""
        return transforms.pose_from_xyzquat(self.pose)


@dataclass(frozen=True)
class Region:
    """A rectangle on the top face of body `on`, axis-aligned, centred at `center` (x, y)."""

    name: str
    on: str
    center: tuple[float, float]
    size: tuple[float, float]
    color: tuple[float, float, float, float] = (0.3, 0.8, 0.3, 0.5)
    line: int | None = field(default=None, compare=False)

    @property
    def lower(self) -> np.ndarray:
        return np.array(self.center) - 0.5 * np.array(self.size)

    @property
    def upper(self) -> np.ndarray:
        return np.array(self.center) + 0.5 * np.array(self.size)


@dataclass(frozen=True)
class Camera:
    eye: tuple[float, float, float]
    target: tuple[float, float, float]
    up: tuple[float, float, float] = (0.0, 0.0, 1.0)
    fov: float = 50.0  # degrees, vertical


@dataclass(frozen=True)
class Scene:
    path: str | None
    robot: RobotSpec
    bodies: tuple[Body, ...] = ()
    regions: tuple[Region, ...] = ()
    camera: Camera | None = None

    def body(self, name: str) -> Body:
        for b in self.bodies:
            if b.name == name:
                return b
        raise KeyError(name)

    def region(self, name: str) -> Region:
        for r in self.regions:
            if r.name == name:
                return r
        raise KeyError(name)

    def has_body(self, name: str) -> bool:
        return any(b.name == name for b in self.bodies)

    def has_region(self, name: str) -> bool:
        return any(r.name == name for r in self.regions)

    @property
    def movable_names(self) -> tuple[str, ...]:
        return tuple(b.name for b in self.bodies if not b.fixed)


def find_modes(domain_path: str | Path) -> Path | None:
    """`modes.toml` beside the domain file, or None."""
    from tampcli.geometry.modes import find_modes as _find

    return _find(domain_path)


def load_modes(path: str | Path, domain: ast.Domain):
    """Read modes.toml (see tampcli.geometry.modes)."""
    from tampcli.geometry.modes import load_modes as _load

    return _load(path, domain)


def find_scene(problem_path: str | Path) -> Path | None:
    """`p01.pddl` -> `p01.scene.toml` beside it, or None when there is none."""
    p = Path(problem_path)
    candidate = p.with_name(p.stem + ".scene.toml")
    return candidate if candidate.is_file() else None


# ------------------------------------------------------------------ loading


def load_scene(path: str | Path, domain: ast.Domain | None = None,
               problem: ast.Problem | None = None, modes=None,
               geometric: bool = True) -> Scene:
    """Read and check a scene file against the problem (and the modes, when given).

    With `geometric`, also build the world once and refuse overlapping bodies
    and a start configuration outside the joint limits or in collision.
    """
    src = read_toml(str(path))
    scene = _build_scene(src)
    if problem is not None:
        scene = _check_against_problem(src, scene, domain, problem)
        if modes is not None and domain is not None:
            check_modes_against_scene(src, scene, modes, domain, problem)
    if geometric:
        from tampcli.geometry.startcheck import check_start_state

        check_start_state(scene, src)
    return scene


def _build_scene(src: TomlSource) -> Scene:
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
            raise src.error(f"region {r.name!r} is on {r.on!r}, which is no object of the scene",
                            "regions", i, "on", "regions.on")
        support = next(b for b in bodies if b.name == r.on)
        if support.shape not in ("box", "cylinder"):
            raise src.error(f"region {r.name!r} must lie on a box or cylinder, {r.on!r} is a "
                            f"{support.shape}", "regions", i, "on", "regions.on")
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
    urdf = r.path("urdf")
    tool_link = r.string("tool_link")
    joints = r.strings("joints")
    if model == "urdf":
        if urdf is None:
            raise r.error("model \"urdf\" needs `urdf`, `tool_link` and `joints`", "model")
        if tool_link is None or joints is None:
            raise r.error("a URDF robot needs `tool_link` and `joints`", "urdf")
    else:
        for key in ("urdf", "tool_link", "joints"):
            if r.has(key):
                raise r.error(f"only for model \"urdf\", not {model!r}", key)
    if model != "planar":
        for key in ("radius", "height"):
            if r.has(key):
                raise r.error(f"only for model \"planar\", not {model!r}", key)
    if start is not None:
        expected = {"panda": 7, "planar": 2}.get(model, len(joints or ()))
        if len(start) != expected:
            raise r.error(f"expected {expected} joint values for the {model} robot, "
                          f"got {len(start)}", "start")
    return RobotSpec(model, base, start, radius, height, urdf, tool_link, joints,
                     line=src.line("robot"))


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
    return Body(name=name, shape=shape, size=size, pose=r.pose("pose"),
                fixed=r.boolean("fixed", False), color=r.color("color", DEFAULT_COLOR),
                mesh=mesh, urdf=urdf, scale=scale, line=src.line("objects", index, "name"))


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


# ------------------------------------------------------- against the problem


def pddl_objects(domain: ast.Domain | None, problem: ast.Problem) -> dict[str, tuple[str, ...]]:
    """Object and constant names -> their types."""
    names = {o.name: o.types for o in problem.objects}
    if domain is not None:
        for c in domain.constants:
            names.setdefault(c.name, c.types)
    return names


def _check_against_problem(src: TomlSource, scene: Scene, domain, problem) -> Scene:
    objects = pddl_objects(domain, problem)
    bodies = []
    for i, b in enumerate(scene.bodies):
        obstacle = b.name not in objects
        if obstacle and not b.fixed:
            raise src.error(f"{b.name!r} is no object of the PDDL problem; an obstacle must say "
                            "`fixed = true`", "objects", i, "name", "objects.name")
        bodies.append(_replace(b, obstacle=obstacle))
    for i, r in enumerate(scene.regions):
        if r.name not in objects:
            raise src.error(f"region {r.name!r} is no object of the PDDL problem", "regions", i,
                            "name", "regions.name")
    return Scene(scene.path, scene.robot, tuple(bodies), scene.regions, scene.camera)


def _replace(body: Body, **changes) -> Body:
    import dataclasses

    return dataclasses.replace(body, **changes)


def check_modes_against_scene(src: TomlSource | None, scene: Scene, modes, domain, problem):
    """Every PDDL object a geometric action can take must have geometry in the scene.

    For each role (`object`, `on`, `to`) of each geometric mode, the objects
    of the parameter's type need a body or a region. Whether the geometry
    fits the role (grasping a region, say) is left to the symbolic
    preconditions and the optimizer.
    """
    objects = pddl_objects(domain, problem)
    parents = _type_parents(domain)
    for mode in modes.values():
        if mode.kind == "none":
            continue
        action = domain.action(mode.action)
        for role in ("object", "on", "to"):
            param = getattr(mode, role)
            if param is None:
                continue
            if param.startswith("?"):
                types = next(p.types for p in action.params if p.name == param)
                candidates = sorted(n for n, t in objects.items()
                                    if any(_is_subtype(tt, types, parents) for tt in t))
            else:
                candidates = [param]
            for name in candidates:
                if scene.has_body(name) or scene.has_region(name):
                    continue
                where = f" ({modes.path}:{mode.line})" if mode.line else ""
                message = (f"no object or region {name!r} in the scene, but action "
                           f"{mode.action!r} may {mode.kind} it ({role} = {param!r}{where})")
                line = src.line("objects") if src is not None else None
                raise SceneError(message, path=scene.path, line=line or 1, key="objects",
                                 source_line=source_line_at(src.text, line or 1)
                                 if src is not None else None)


def _type_parents(domain) -> dict[str, tuple[str, ...]]:
    parents: dict[str, tuple[str, ...]] = {}
    if domain is not None:
        for t in domain.types:
            parents[t.name] = tuple(x for x in t.types if x != t.name)
    return parents


def _is_subtype(t: str, wanted: tuple[str, ...], parents) -> bool:
    seen = set()
    stack = [t]
    while stack:
        cur = stack.pop()
        if cur in wanted or "object" in wanted:
            return True
        if cur in seen:
            continue
        seen.add(cur)
        stack.extend(parents.get(cur, ()))
    return False
