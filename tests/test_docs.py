"""The repository stands alone, and the worked examples of docs/formats.md are real."""

import json
import re
import subprocess
import sys

from tests.conftest import ROOT

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

FORMATS = ROOT / "docs" / "formats.md"
# Spelled in pieces, so that this file does not itself cite what it looks for.
OUTSIDE = ("../" + "shared", "SPEC" + ".md", "/work/" + "shared")
# Recorded benchmark output may quote old paths: it is a record, not a reference.
RECORDS = "bench/results/"

# A fenced block, optionally announced as a copy of a file of the repository.
_BLOCK = re.compile(r"^(?:<!-- same as (?P<same>\S+) -->\n)?```(?P<lang>\w*)\n(?P<body>.*?)^```$",
                    re.MULTILINE | re.DOTALL)


def _blocks(lang: str) -> list[re.Match]:
    return [m for m in _BLOCK.finditer(FORMATS.read_text()) if m.group("lang") == lang]


def test_no_tracked_file_cites_anything_outside_the_repository():
    listing = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True,
                             check=True).stdout.decode()
    names = [n for n in listing.split("\0") if n and not n.startswith(RECORDS)]
    assert len(names) > 100  # the listing is the repository, not an empty folder
    hits = [f"{name}: {text}" for name in names if (ROOT / name).is_file()
            for text in OUTSIDE if text.encode() in (ROOT / name).read_bytes()]
    assert hits == []


def test_toml_examples_parse():
    blocks = _blocks("toml")
    assert len(blocks) >= 4
    for block in blocks:
        tomllib.loads(block.group("body"))


def test_toml_examples_said_to_be_repository_files_are_those_files():
    copies = [b for b in _blocks("toml") if b.group("same")]
    assert {b.group("same") for b in copies} == {"domains/arm-pick-place/modes.toml",
                                                 "problems/arm-pick-place/p01.scene.toml"}
    for block in copies:
        shown = tomllib.loads(block.group("body"))
        assert shown == tomllib.loads((ROOT / block.group("same")).read_text())


def test_json_examples_parse():
    blocks = _blocks("json")
    assert len(blocks) >= 6
    for block in blocks:
        json.loads(block.group("body"))
    lines = [line for block in _blocks("jsonl") for line in block.group("body").splitlines()]
    assert lines
    for line in lines:
        assert isinstance(json.loads(line), dict)


def test_the_solution_example_is_a_valid_solution(cli, tmp_path, monkeypatch):
    """The full solution.json shown passes `validate`, geometry included."""
    solutions = [json.loads(b.group("body")) for b in _blocks("json")
                 if '"version"' in b.group("body")]
    assert len(solutions) == 1
    solution = solutions[0]
    path = tmp_path / "solution.json"
    path.write_text(json.dumps(solution))
    monkeypatch.chdir(ROOT)  # the paths it records are relative to the repository
    run = cli("validate", solution["domain"], solution["problem"], path, "--json")
    assert run.code == 0, run.out + run.err
    report = json.loads(run.out)
    assert report["geometry"] == "checked"
    assert report["violations"] == []
