"""Every file under malformed/ fails with a SceneError at the line and key its header names.

Header: `# expect: line=N key=KEY match=TEXT` (an empty key: the error has none).
Scenes are checked against data/domain.pddl, data/p01.pddl and data/modes.toml;
mesh and URDF files the scenes name are in malformed/files/. Each file is
refused twice: by the loaders, and by `tampcli check` (exit 2, located, no
traceback).
"""

import re
from pathlib import Path

import pytest

from tampcli.errors import SceneError
from tampcli.optimize.modes import load_modes
from tampcli.pddl import parser

from .loading import load_checked

HERE = Path(__file__).parent
CASES = sorted((HERE / "malformed").glob("*.toml"))
EXPECT = re.compile(r"^# expect: line=(\d+) key=(\S*) match=(.*)$")
DOMAIN, PROBLEM = HERE / "data" / "domain.pddl", HERE / "data" / "p01.pddl"


def _expected(path: Path) -> tuple[int, str | None, str]:
    m = EXPECT.match(path.read_text().splitlines()[0])
    assert m, f"{path.name}: first line must be '# expect: line=N key=KEY match=TEXT'"
    return int(m.group(1)), m.group(2) or None, m.group(3)


@pytest.fixture(scope="module")
def pddl():
    domain = parser.parse_domain_file(str(DOMAIN))
    problem = parser.parse_problem_file(str(PROBLEM))
    return domain, problem, load_modes(HERE / "data" / "modes.toml", domain)


def test_catalog_is_large():
    assert len(CASES) >= 40


@pytest.mark.parametrize("path", CASES, ids=[p.name for p in CASES])
def test_malformed_file_fails_located(path, pddl):
    domain, problem, modes = pddl
    line, key, match = _expected(path)
    with pytest.raises(SceneError) as info:
        if path.name.endswith(".modes.toml"):
            load_modes(path, domain)
        else:
            load_checked(path, domain, problem, modes)
    error = info.value
    assert error.path == str(path)
    assert (error.line, error.key) == (line, key), error.render()
    assert match in error.message, error.render()
    rendered = error.render()
    assert rendered.startswith(f"{path}:{line}")
    if error.line is not None:
        assert error.source_line == path.read_text().splitlines()[line - 1]


@pytest.mark.parametrize("path", CASES, ids=[p.name for p in CASES])
def test_malformed_file_fails_through_the_cli(path, cli):
    line, key, match = _expected(path)
    flag = "--modes" if path.name.endswith(".modes.toml") else "--scene"
    run = cli("check", DOMAIN, PROBLEM, flag, path)
    assert run.code == 2, run.err
    assert "Traceback" not in run.out + run.err
    assert "internal error" not in run.err
    located = re.escape(f"{path}:{line}") + r"(:\d+)?: " + (re.escape(f"{key}: ") if key else "")
    assert re.match(located, run.err), run.err
    assert match in run.err.splitlines()[0], run.err
