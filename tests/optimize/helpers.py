"""Shared test scenes: the real loaders, skeletons from plan text."""

from __future__ import annotations

from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from tampcli.geometry.scene import load_scene as _load_scene
from tampcli.optimize.modes import load_modes as _load_modes
from tampcli.pddl import parser

ROOT = Path(__file__).resolve().parents[2]
SCENES = Path(__file__).resolve().parent / "scenes"
DOMAIN_OF = {"wall": "arm-pick-place", "planar": "planar-push"}


@dataclass(frozen=True)
class Op:
    """A ground action as the search produces it (name, schema, arguments)."""

    name: str
    action: str
    args: tuple[str, ...]


def ops(*texts: str) -> list[Op]:
    out = []
    for t in texts:
        parts = t.strip("()").split()
        out.append(Op(t, parts[0], tuple(parts[1:])))
    return out


def domain_path(scene_name: str) -> Path:
    return ROOT / "domains" / DOMAIN_OF[scene_name] / "domain.pddl"


def load(scene_name: str):
    """(domain, problem, scene, modes) of a test scene, through the product's loaders."""
    domain = parser.parse_domain_file(domain_path(scene_name))
    problem = parser.parse_problem_file(SCENES / f"{scene_name}.pddl")
    scene = _load_scene(SCENES / f"{scene_name}.scene.toml", domain, problem)
    modes = _load_modes(domain_path(scene_name).with_name("modes.toml"), domain)
    return domain, problem, scene, modes


@contextmanager
def lowered_folder(folder: Path, stem: str, skeleton):
    """A problem written blind as one folder (domain.pddl, modes.toml, STEM.pddl,
    STEM.scene.toml), `skeleton` lowered on its own World and CollisionChecker."""
    from tampcli.geometry.collision import CollisionChecker
    from tampcli.geometry.world import World
    from tampcli.optimize.options import OptimizeOptions
    from tampcli.optimize.problem import lower

    domain = parser.parse_domain_file(folder / "domain.pddl")
    problem = parser.parse_problem_file(folder / f"{stem}.pddl")
    scene = _load_scene(folder / f"{stem}.scene.toml", domain, problem)
    modes = _load_modes(folder / "modes.toml", domain)
    with World(scene) as world:
        yield lower(skeleton, scene, modes, world, OptimizeOptions(), domain=domain,
                    checker=CollisionChecker(world))


@contextmanager
def lowered_library(folder: Path, domain_folder: Path, stem: str, skeleton):
    """A library problem (its domain and modes in domains/, the rest in problems/),
    `skeleton` lowered on its own World and CollisionChecker."""
    from tampcli.geometry.collision import CollisionChecker
    from tampcli.geometry.world import World
    from tampcli.optimize.problem import lower

    domain = parser.parse_domain_file(domain_folder / "domain.pddl")
    problem = parser.parse_problem_file(folder / f"{stem}.pddl")
    scene = _load_scene(folder / f"{stem}.scene.toml", domain, problem)
    modes = _load_modes(domain_folder / "modes.toml", domain)
    with World(scene) as world:
        yield lower(skeleton, scene, modes, world, domain=domain,
                    checker=CollisionChecker(world))


def central_differences(f, x, h: float = 1e-6) -> np.ndarray:
    """The Jacobian of f (vector -> vector) at x by central differences, (m, n)."""
    cols = []
    for i in range(len(x)):
        e = np.zeros_like(x)
        e[i] = h
        cols.append((f(x + e) - f(x - e)) / (2 * h))
    return np.array(cols).T


def solved_in_physics(cli, folder: Path, tmp_path: Path, time_limit: int = 60,
                      domain: Path | None = None, problem: Path | None = None) -> dict:
    """`validate --json --physics` of `solve`'s answer to folder's domain.pddl and
    p.pddl (or `domain` and `problem`), both asserted to succeed; the replay's
    `physics` object."""
    import json

    domain = domain or folder / "domain.pddl"
    problem = problem or folder / "p.pddl"
    out = tmp_path / "solution.json"
    solved = cli("solve", "--quiet", "--time-limit", str(time_limit), "--out", out, domain,
                 problem)
    assert solved.code == 0, solved.err
    run = cli("validate", "--json", "--physics", domain, problem, out)
    data = json.loads(run.out)
    assert run.code == 0, data["violations"]
    return data["physics"]


def path_from_keyframes(problem):
    """The path stage of `problem` warm from its keyframes, which must solve."""
    from tampcli.optimize.solve import solve

    kf = solve(problem, "keyframes")
    assert kf.solved, kf.worst_constraint
    return solve(problem, "path", warm=kf)
