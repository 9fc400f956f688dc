"""What a replay reads: the solution, its scene (and modes), checked against each other."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

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
        sol, path, anchor = solution_file.read(source), str(source), Path(source)
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


def _check_shape(sol: Solution, path: str) -> None:
    """What `solution.read` checks for a file, for a Solution built in memory too."""
    n = len(sol.trajectory)
    for i, q in enumerate(sol.trajectory):
        if len(q) != len(sol.trajectory[0]):
            raise SolutionFileError("waypoints of different lengths", path, key="trajectory")
        if not all(math.isfinite(v) for v in q):
            raise SolutionFileError(f"waypoint {i} holds a non-finite value", path,
                                    key="trajectory")
    for i, phase in enumerate(sol.phases):
        if not 0 <= phase.start <= phase.end < n:
            raise SolutionFileError(f"start/end out of range (trajectory has {n} waypoints)",
                                    path, key=f"phases[{i}]")
    for name, poses in sol.objects.items():
        if sol.phases and len(poses) != len(sol.phases) + 1:
            raise SolutionFileError(f"expected {len(sol.phases) + 1} poses (one per phase "
                                    f"boundary), found {len(poses)}", path, key=f"objects.{name}")
        if any(len(pose) != 7 or not all(math.isfinite(v) for v in pose) for pose in poses):
            raise SolutionFileError("each pose needs 7 finite numbers [x y z qx qy qz qw]",
                                    path, key=f"objects.{name}")


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
    """The solution must fit the scene: same joints, known objects."""
    sol, path = inputs.solution, inputs.path
    width = len(sol.trajectory[0])
    if width != world.n:
        raise SolutionFileError(f"waypoints have {width} joint values but the scene's robot has "
                                f"{world.n} ({', '.join(world.joint_names)})", path,
                                key="trajectory")
    joints = tuple(sol.robot.get("joints") or ())
    if joints and joints != tuple(world.joint_names):
        raise SolutionFileError(f"joints {', '.join(joints)} do not match the scene's robot "
                                f"({', '.join(world.joint_names)})", path, key="robot.joints")
    bodies = set(world.body_names)
    for name in sol.objects:
        if name not in bodies:
            raise SolutionFileError(f"{name!r} is no body of the scene {inputs.scene.path}",
                                    path, key=f"objects.{name}")
    for i, phase in enumerate(sol.phases):
        if phase.attached is not None and phase.attached not in sol.objects:
            raise SolutionFileError(f"attached object {phase.attached!r} has no poses in "
                                    "`objects`", path, key=f"phases[{i}].attached")
