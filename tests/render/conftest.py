"""Fixtures for the render tests: solution files built by render_solutions.py."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from render_solutions import PANDA, panda_solution, planar_solution

from tampcli import solution as solution_file
from tampcli.solution import Solution


@pytest.fixture(scope="session")
def panda_json(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("panda") / "solution.json"
    solution_file.write(panda_solution(), path)
    return path


@pytest.fixture(scope="session")
def planar_json(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("planar") / "solution.json"
    solution_file.write(planar_solution(), path)
    return path


@pytest.fixture
def relative_copy(tmp_path) -> Path:
    """The panda problem copied beside a solution that names it relatively."""
    folder = tmp_path / "problem"
    shutil.copytree(PANDA, folder)
    sol = panda_solution(folder)
    sol = Solution(**{**sol.__dict__, "domain": "problem/domain.pddl",
                      "problem": "problem/p01.pddl", "scene": "problem/p01.scene.toml"})
    path = tmp_path / "solution.json"
    solution_file.write(sol, path)
    return path
