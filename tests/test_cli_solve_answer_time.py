"""`solve --json`'s `stats.answer_since_start`: when the answer returned was found, from
the solve's start (blind30 DOC_GAPS 11: only the first solution's time was given)."""

import json
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOMAINS, PROBLEMS = ROOT / "domains", ROOT / "problems"


def _stats(cli, tmp_path, domain, problem):
    out = tmp_path / f"{domain}-{problem}.json"
    run = cli("solve", "--quiet", "--jobs", "1", "--out", out, DOMAINS / domain / "domain.pddl",
              PROBLEMS / domain / f"{problem}.pddl")
    assert run.code == 0, run.err
    return json.loads(out.read_text())["stats"]


def test_a_later_better_answer_is_timed_when_it_was_found(cli, tmp_path):
    """arm-pick-place p03: the first skeleton answers, the second does better."""
    stats = _stats(cli, tmp_path, "arm-pick-place", "p03")
    first, answer = stats["first_solution_since_start"], stats["answer_since_start"]
    assert first < answer <= stats["seconds"]["total"]


def test_a_first_answer_kept_is_timed_as_the_first(cli, tmp_path):
    """arm-pick-place p01: one skeleton, one answer."""
    stats = _stats(cli, tmp_path, "arm-pick-place", "p01")
    assert abs(stats["answer_since_start"] - stats["first_solution_since_start"]) < 1e-3
