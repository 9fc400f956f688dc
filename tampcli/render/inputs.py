"""What a replay reads: the solution, its scene (and modes), checked against each other."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from tampcli import solution as solution_file
from tampcli.errors import SolutionFileError
from tampcli.solution import Solution


@dataclass(frozen=True)
class RenderInputs:
    solution: Solution
    path: str  # the solution file, or "<solution>" for an in-memory one
    scene: object  # geometry.scene.Scene
    problem_name: str
    modes: object | None = None  # geometry.scene.Modes, when the solution names one


def load_inputs(source: Solution | str | Path) -> RenderInputs:
    """Read a solution (a path or a value) and the scene it names.

    Paths recorded in an in-memory Solution are taken relative to the working
    directory, as `solve` wrote them.
    """
    if isinstance(source, Solution):
        sol, path, anchor = source, "<solution>", Path.cwd() / "solution.json"
    else:
        sol, path, anchor = _read(source), str(source), Path(source)
    if not sol.trajectory:
        raise SolutionFileError(f"nothing to render: no trajectory (status {sol.status}"
                                + (f": {sol.reason}" if sol.reason else "") + ")", path,
                                key="trajectory")
    _check_shape(sol, path)
    if sol.scene is None:
        raise SolutionFileError("names no scene file: a symbolic solution has nothing to "
                                "render", path, key="scene")
    from tampcli.geometry.scene import load_scene
    from tampcli.pddl import parser

    domain = problem = None
    domain_path = solution_file.resolve_input(anchor, sol.domain)
    problem_path = solution_file.resolve_input(anchor, sol.problem)
    if domain_path is not None and domain_path.is_file():
        domain = parser.parse_domain_file(str(domain_path))
    if problem_path is not None and problem_path.is_file():
        problem = parser.parse_problem_file(str(problem_path))
    scene_path = solution_file.resolve_input(anchor, sol.scene)
    if not scene_path.is_file():
        raise SolutionFileError(f"scene file not found: {sol.scene} (looked beside the "
                                "solution and in the working directory)", path, key="scene")
    scene = load_scene(scene_path, domain, problem, geometric=False)
    modes = _load_modes(anchor, sol, domain)
    name = problem.name if problem is not None else Path(sol.problem or "").stem
    return RenderInputs(sol, path, scene, name, modes)


def _read(path: str | Path) -> Solution:
    """`solution.read`, after the type checks it leaves to its readers: it
    converts `plan`, `robot.joints` and `skeletons` without looking at them."""
    path = str(path)
    try:
        data = json.loads(Path(path).read_text())
    except UnicodeDecodeError as err:
        raise SolutionFileError(f"not UTF-8 text (byte {err.start})", path) from None
    except RecursionError:
        raise SolutionFileError("JSON nested too deeply", path) from None
    except (OSError, ValueError):
        data = None  # `read` says what and where
    if isinstance(data, dict):
        _check_types(data, path)
    return solution_file.read(path)


def _check_types(data: dict, path: str) -> None:
    """Raw JSON values `solution.read` would choke on; a missing key is its business."""
    if "plan" in data:
        _strings(data["plan"], path, "plan")
    robot = data.get("robot")
    if isinstance(robot, dict) and "joints" in robot:
        _strings(robot["joints"], path, "robot.joints")
    skeletons = data.get("skeletons")
    if not isinstance(skeletons, list):
        return
    for i, record in enumerate(skeletons):
        key = f"skeletons[{i}]"
        if not isinstance(record, dict):
            raise SolutionFileError("expected an object", path, key=key)
        if "rank" in record and not _is_int(record["rank"]):
            raise SolutionFileError(f"expected an integer, got {record['rank']!r}", path,
                                    key=f"{key}.rank")
        if "plan" in record:
            _strings(record["plan"], path, f"{key}.plan")
        seconds = record.get("seconds")
        if seconds is not None and not _is_number(seconds):
            raise SolutionFileError(f"expected a number, got {seconds!r}", path,
                                    key=f"{key}.seconds")


def _check_shape(sol: Solution, path: str) -> None:
    """The solution on its own, from a file or built in memory: types `read`
    passes through, finite numbers, phases that tile the trajectory, a pose
    per phase boundary."""
    for key in ("domain", "problem", "scene", "modes"):
        value = getattr(sol, key)
        if value is not None and not isinstance(value, str):
            raise SolutionFileError(f"expected a path (a string), got {value!r}", path, key=key)
    _strings(sol.plan, path, "plan")
    model = sol.robot.get("model")
    if model is not None and not isinstance(model, str):
        raise SolutionFileError(f"expected a string, got {model!r}", path, key="robot.model")
    n = len(sol.trajectory)
    for i, q in enumerate(sol.trajectory):
        if len(q) != len(sol.trajectory[0]):
            raise SolutionFileError("waypoints of different lengths", path, key="trajectory")
        if not all(_finite(v) for v in q):
            raise SolutionFileError(f"waypoint {i} holds a non-finite value", path,
                                    key="trajectory")
    _check_phases(sol, n, path)
    for name, poses in sol.objects.items():
        key = f"objects.{name}"
        if len(poses) != len(sol.phases) + 1:
            raise SolutionFileError(f"expected {len(sol.phases) + 1} poses (one before the "
                                    f"first phase, one after each), found {len(poses)}",
                                    path, key=key)
        for k, pose in enumerate(poses):
            if len(pose) != 7 or not all(_finite(v) for v in pose):
                raise SolutionFileError(f"pose {k}: expected 7 finite numbers "
                                        "[x y z qx qy qz qw]", path, key=key)
            if math.hypot(*pose[3:]) < 1e-9:
                raise SolutionFileError(f"pose {k} has a zero quaternion (no rotation is "
                                        "[0, 0, 0, 1])", path, key=key)


def _check_phases(sol: Solution, n: int, path: str) -> None:
    """Phases cover the trajectory exactly: the first starts at waypoint 0, each
    starts where the previous one ended, the last ends at the last waypoint."""
    if not sol.phases:
        if n > 1:
            raise SolutionFileError(f"no phases for a trajectory of {n} waypoints: phases "
                                    "must cover it", path, key="phases")
        return
    expected = 0
    for i, phase in enumerate(sol.phases):
        key = f"phases[{i}]"
        for field in ("action", "attached"):
            value = getattr(phase, field)
            if value is not None and not isinstance(value, str):
                raise SolutionFileError(f"expected a string or null, got {value!r}", path,
                                        key=f"{key}.{field}")
        if not (_is_int(phase.start) and _is_int(phase.end)
                and 0 <= phase.start <= phase.end < n):
            raise SolutionFileError(f"start/end out of range (trajectory has {n} waypoints)",
                                    path, key=key)
        if phase.start != expected:
            where = "the first phase starts at waypoint 0" if i == 0 else \
                f"a phase starts where the previous one ended (phases[{i - 1}].end)"
            raise SolutionFileError(f"starts at {phase.start}, expected {expected}: {where}",
                                    path, key=f"{key}.start")
        expected = phase.end
    if expected != n - 1:
        raise SolutionFileError(f"ends at {expected}, expected {n - 1}: the last phase ends "
                                f"at the last waypoint", path,
                                key=f"phases[{len(sol.phases) - 1}].end")


def _strings(value, path: str, key: str) -> None:
    if not isinstance(value, (list, tuple)):
        raise SolutionFileError(f"expected a list of strings, got {value!r}", path, key=key)
    for i, item in enumerate(value):
        if not isinstance(item, str):
            raise SolutionFileError(f"entry {i} is not a string: {item!r}", path, key=key)


def _is_int(value) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _finite(value) -> bool:
    """JSON integers have no size limit: one too large for a float is not finite."""
    try:
        return math.isfinite(value)
    except OverflowError:
        return False


def _load_modes(anchor: Path, sol: Solution, domain):
    """The modes file the solution names, to tell geometric actions from symbolic
    ones; without it, replay judges by what each action does to the world."""
    modes_path = solution_file.resolve_input(anchor, sol.modes)
    if modes_path is None or not modes_path.is_file() or domain is None:
        return None
    from tampcli.geometry.scene import load_modes

    return load_modes(modes_path, domain)


def mode_kind_of(modes):
    """A `mode_kind(action) -> kind | None` callable over a Modes value (None: unknown)."""
    from tampcli.render.replay import schema_of

    def mode_kind(action: str) -> str | None:
        if modes is None:
            return None
        return modes.get_mode(schema_of(action)).kind

    return mode_kind


def check_against_world(inputs: RenderInputs, world) -> None:
    """The solution must fit the scene: the same robot (model, joints, tool),
    waypoints inside its joint limits, poses for exactly its movable bodies."""
    sol, path = inputs.solution, inputs.path
    scene_path = inputs.scene.path
    model, scene_model = sol.robot.get("model"), inputs.scene.robot.model
    if model is None:
        raise SolutionFileError(f"missing (the scene's robot is {scene_model!r})", path,
                                key="robot.model")
    if model != scene_model:
        raise SolutionFileError(f"{model!r} but the scene {scene_path} has a {scene_model!r} "
                                "robot", path, key="robot.model")
    width = len(sol.trajectory[0])
    if width != world.n:
        raise SolutionFileError(f"waypoints have {width} joint values but the scene's robot has "
                                f"{world.n} ({', '.join(world.joint_names)})", path,
                                key="trajectory")
    joints = tuple(sol.robot.get("joints") or ())
    if joints and joints != tuple(world.joint_names):
        raise SolutionFileError(f"joints {', '.join(joints)} do not match the scene's robot "
                                f"({', '.join(world.joint_names)})", path, key="robot.joints")
    tool = sol.robot.get("tool_link")
    if tool is not None and tool != world.tool_link:
        raise SolutionFileError(f"{tool!r} but the scene's robot has tool link "
                                f"{world.tool_link!r}", path, key="robot.tool_link")
    _check_limits(sol, world, path)
    movable, fixed = set(world.movable_names), set(world.body_names) - set(world.movable_names)
    for name in sol.objects:
        if name in fixed:
            raise SolutionFileError(f"{name!r} is a fixed body of the scene {scene_path}: "
                                    "`objects` holds the movable bodies only", path,
                                    key=f"objects.{name}")
        if name not in movable:
            raise SolutionFileError(f"{name!r} is no body of the scene {scene_path}",
                                    path, key=f"objects.{name}")
    missing = [name for name in world.movable_names if name not in sol.objects]
    if missing:
        raise SolutionFileError(f"no poses for {', '.join(map(repr, missing))}: `objects` needs "
                                f"every movable body of the scene {scene_path}", path,
                                key="objects")
    for i, phase in enumerate(sol.phases):
        if phase.attached is not None and phase.attached not in sol.objects:
            raise SolutionFileError(f"attached object {phase.attached!r} has no poses in "
                                    "`objects`", path, key=f"phases[{i}].attached")


def _check_limits(sol: Solution, world, path: str) -> None:
    """Waypoints inside the joint limits, with `validate`'s tolerance: solve's
    optimizer keeps them inside exactly and JSON round-trips floats exactly, so
    the tolerance only forgives rounding by other writers; a joint whose URDF
    gives no limits (upper < lower) is not checked."""
    from tampcli.optimize.verify import LIMIT

    q = np.asarray(sol.trajectory, dtype=float)
    lower, upper = np.asarray(world.lower), np.asarray(world.upper)
    limited = lower <= upper
    excess = np.where(limited, np.maximum(lower - LIMIT - q, q - upper - LIMIT), 0.0)
    outside = np.argwhere(excess > 0.0)
    if len(outside):
        i, j = (int(v) for v in outside[0])
        raise SolutionFileError(f"waypoint {i}: joint {world.joint_names[j]} = {q[i, j]:.6g} "
                                f"outside its limits [{lower[j]:.6g}, {upper[j]:.6g}] "
                                f"(tolerance {LIMIT:g})", path, key="trajectory")
