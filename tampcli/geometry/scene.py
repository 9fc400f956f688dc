"""scene.toml -> Scene: the geometry of one problem (see docs/formats.md, "scene.toml").

Obstacles: a body whose `name` is not an object (or constant) of the PDDL
problem is an obstacle. An obstacle must say `fixed = true`; it then takes
part in collisions but never in the symbolic plan. A body named in the PDDL
problem is movable unless it says `fixed = true` (a table, a shelf).

Every error is a SceneError located as `path:line: key: what is wrong`; the
line is the one of the offending key, or of its `[[objects]]` entry.
"""

from __future__ import annotations

from pathlib import Path

from tampcli.geometry.locate import find_modes, find_scene
from tampcli.geometry.model import (
    COLORS,
    DEFAULT_COLOR,
    PANDA_READY,
    ROBOT_MODELS,
    SHAPES,
    Body,
    Camera,
    Region,
    RobotSpec,
    Scene,
)
from tampcli.geometry.scene_check import (
    check_against_problem,
    check_modes_against_scene,
    pddl_objects,
)
from tampcli.geometry.scene_parse import build_scene
from tampcli.geometry.tomlsrc import TomlSource, read_toml
from tampcli.pddl import ast

__all__ = [
    "COLORS", "DEFAULT_COLOR", "PANDA_READY", "ROBOT_MODELS", "SHAPES", "Body", "Camera",
    "Region", "RobotSpec", "Scene", "check_modes_against_scene", "find_modes",
    "find_scene", "load_scene", "pddl_objects", "read_scene",
]


# ------------------------------------------------------------------ loading


def load_scene(path: str | Path, domain: ast.Domain | None = None,
               problem: ast.Problem | None = None, modes=None, *,
               geometric: bool = False) -> Scene:
    """Read and check a scene file against the problem (and the modes, when given).

    The start state is not checked here: that takes a World, which the caller
    builds once and hands to `startcheck.check_start_state`. `geometric` is
    accepted and ignored, for callers written when loading built a World of its own.
    """
    return read_scene(path, domain, problem, modes)[0]


def read_scene(path: str | Path, domain: ast.Domain | None = None,
               problem: ast.Problem | None = None, modes=None) -> tuple[Scene, TomlSource]:
    """`load_scene`, and the parsed file that locates later errors (the start check's)."""
    src = read_toml(str(path))
    scene = build_scene(src)
    if problem is not None:
        scene = check_against_problem(src, scene, domain, problem)
        if modes is not None and domain is not None:
            check_modes_against_scene(src, scene, modes, domain, problem)
    return scene, src
