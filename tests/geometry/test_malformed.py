"""Every file under malformed/ fails with a SceneError at the line and key its header names.

Header: `# expect: line=N key=KEY match=TEXT` (an empty key: the error has none).
Scenes are checked against data/domain.pddl, data/p01.pddl and data/modes.toml.
"""

import re
from pathlib import Path

import pytest

from tampcli.errors import SceneError
from tampcli.geometry.scene import load_modes, load_scene
from tampcli.pddl import parser

HERE = Path(__file__).parent
CASES = sorted((HERE / "malformed").glob("*.toml"))
EXPECT = re.compile(r"^# expect: line=(\d+) key=(\S*) match=(.*)$")


@pytest.fixture(scope="module")
def pddl():
    domain = parser.parse_domain_file(str(HERE / "data" / "domain.pddl"))
    problem = parser.parse_problem_file(str(HERE / "data" / "p01.pddl"))
    return domain, problem, load_modes(HERE / "data" / "modes.toml", domain)


def test_catalog_is_large():
    assert len(CASES) >= 40


@pytest.mark.parametrize("path", CASES, ids=[p.name for p in CASES])
def test_malformed_file_fails_located(path, pddl):
    domain, problem, modes = pddl
    m = EXPECT.match(path.read_text().splitlines()[0])
    assert m, f"{path.name}: first line must be '# expect: line=N key=KEY match=TEXT'"
    line, key, match = int(m.group(1)), m.group(2) or None, m.group(3)
    with pytest.raises(SceneError) as info:
        if path.name.endswith(".modes.toml"):
            load_modes(path, domain)
        else:
            load_scene(path, domain, problem, modes=modes)
    error = info.value
    assert error.path == str(path)
    assert (error.line, error.key) == (line, key), error.render()
    assert match in error.message, error.render()
    rendered = error.render()
    assert rendered.startswith(f"{path}:{line}")
    if error.line is not None:
        assert error.source_line == path.read_text().splitlines()[line - 1]
