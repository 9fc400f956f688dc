"""The registry of mode kinds: complete kinds, names only there, modes.toml checked against it."""

import inspect
import re
from pathlib import Path

import pytest

from tampcli.optimize.kinds import KINDS, SYMBOLIC, ModeKind

from .helpers import ROOT

INTERFACE = sorted(ModeKind.__abstractmethods__)
ROLES = ("object", "on", "to")


def test_the_interface_is_the_whole_life_of_a_kind():
    assert set(INTERFACE) >= {"lower", "grip", "final_rows", "guess", "reseed",
                              "keyframe_rows", "switch", "phases", "check"}


@pytest.mark.parametrize("name", sorted(KINDS))
def test_each_registered_kind_implements_the_whole_interface(name):
    kind = KINDS[name]
    assert isinstance(kind, ModeKind) and kind.name == name
    assert not inspect.isabstract(type(kind))
    for method in INTERFACE:
        assert getattr(type(kind), method) is not getattr(ModeKind, method), method
    assert set(kind.required) | set(kind.optional) <= set(ROLES)
    assert not set(kind.required) & set(kind.optional)
    assert isinstance(kind.geometric, bool) and isinstance(kind.places, bool)
    assert kind.fingers in (None, True, False) and isinstance(kind.holds, bool)


def test_the_kinds_of_the_shipped_domains_are_registered():
    used = set()
    for path in sorted((ROOT / "domains").glob("*/modes.toml")):
        used |= set(re.findall(r'^mode\s*=\s*"([^"]+)"', path.read_text(), re.M))
    assert used and used <= set(KINDS)
    assert SYMBOLIC.name in KINDS and not SYMBOLIC.geometric


def test_kind_names_are_spelled_only_in_the_kinds_package():
    """Every other module asks an action's kind instead of naming it."""
    package = ROOT / "tampcli"
    kinds = package / "optimize" / "kinds"
    geometric = [k for k in KINDS if KINDS[k].geometric]
    pattern = re.compile("|".join(f'"{re.escape(k)}"' for k in geometric))
    found = [f"{path.relative_to(ROOT)}:{i}: {line.strip()}"
             for path in sorted(package.rglob("*.py")) if kinds not in path.parents
             for i, line in enumerate(path.read_text().splitlines(), 1)
             if pattern.search(line) and not _caption(path, line)]
    assert found == []


def _caption(path: Path, line: str) -> bool:
    # The video calls a free motion phase "move" in its captions: a word shown,
    # not a mode's name.
    return path.name == "replay.py" and "label" in line


def test_an_unknown_mode_is_a_located_error_naming_the_registry(tmp_path, cli):
    domain = ROOT / "domains" / "arm-pick-place" / "domain.pddl"
    problem = ROOT / "problems" / "arm-pick-place" / "p01.pddl"
    modes = tmp_path / "modes.toml"
    modes.write_text('[pick]\n# lifts ?b\nmode = "lift"\nobject = "?b"\n')
    run = cli("check", domain, problem, "--modes", modes)
    assert run.code == 2, run.err
    assert "Traceback" not in run.out + run.err
    first = run.err.splitlines()[0]
    assert first.startswith(f"{modes}:3"), run.err
    assert "unknown mode 'lift'" in first
    for name in KINDS:
        assert repr(name) in first or f" {name}" in first, (name, first)
