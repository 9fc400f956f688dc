"""What a replay reads: the solution, its scene (and modes), checked against each other."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from tampcli import solution as solution_file
from tampcli.errors import SolutionFileError
from tampcli.solution import Solution
from tampcli.solution_fit import check_fits_world
from tampcli.solution_read import SolutionFile, check_solution, read_solution


@dataclass(frozen=True)
class RenderInputs:
    """`solution` is the canonical form (arm columns, one motion per gap between
    actions) that replay consumes; `file` holds the solution as written."""

    solution: Solution
    path: str  # the solution file, or "<solution>" for an in-memory one
    scene: object  # geometry.scene.Scene
    problem_name: str
    modes: object | None = None  # geometry.scene.Modes, when the solution names one
    file: SolutionFile | None = None


def load_inputs(source: Solution | str | Path) -> RenderInputs:
    """Read a solution (a path or a value) and the scene it names.

    Paths recorded in an in-memory Solution are taken relative to the working
    directory, as `solve` wrote them.
    """
    if isinstance(source, Solution):
        checked, anchor = check_solution(source), Path.cwd() / "solution.json"
    else:
        checked, anchor = read_solution(source), Path(source)
    sol, path = checked.canonical, checked.path
    if not sol.trajectory:
        raise SolutionFileError(f"nothing to render: no trajectory (status {sol.status}"
                                + (f": {sol.reason}" if sol.reason else "") + ")", path,
                                key="trajectory")
    if sol.scene is None:
        raise SolutionFileError("names no scene file: a symbolic solution has nothing to "
                                "render", path, key="scene")
    from tampcli.geometry.scene import load_scene
    from tampcli.pddl.load import load

    domain = problem = None
    domain_path = solution_file.resolve_input(anchor, sol.domain)
    problem_path = solution_file.resolve_input(anchor, sol.problem)
    if domain_path is not None and domain_path.is_file():
        has_problem = problem_path is not None and problem_path.is_file()
        loaded = load(str(domain_path), str(problem_path) if has_problem else None)
        domain, problem = loaded.domain, loaded.problem
    scene_path = solution_file.resolve_input(anchor, sol.scene)
    if not scene_path.is_file():
        raise SolutionFileError(f"scene file not found: {sol.scene} (looked beside the "
                                "solution and in the working directory)", path, key="scene")
    scene = load_scene(scene_path, domain, problem, geometric=False)
    modes = _load_modes(anchor, sol, domain)
    name = problem.name if problem is not None else Path(sol.problem or "").stem
    return RenderInputs(sol, path, scene, name, modes, checked)


def _load_modes(anchor: Path, sol: Solution, domain):
    """The modes file the solution names, to tell geometric actions from symbolic
    ones; without it, replay judges by what each action does to the world."""
    modes_path = solution_file.resolve_input(anchor, sol.modes)
    if modes_path is None or not modes_path.is_file() or domain is None:
        return None
    from tampcli.optimize.modes import load_modes

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
    """The solution must fit the scene (see solution_fit) and keep its waypoints
    inside the robot's joint limits."""
    check_fits_world(inputs.file or check_solution(inputs.solution, inputs.path), world,
                     inputs.scene.path)
    _check_limits(inputs.solution, world, inputs.path)


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
