"""The robust-arm problems: written before the solver was tuned on them, one
pair per failure class (problems/robust-arm/README.md). `check` must accept
each; the slow tests solve each within its time limit and judge the solution
by `tampcli validate` and by the independent checker. Many are expected to
fail today: that is what they are for."""
import time
from pathlib import Path

import pytest

from tests.robustness.checker import check_solution

ROOT = Path(__file__).resolve().parents[2]
DOMAIN = ROOT / "domains" / "robust-arm" / "domain.pddl"
PROBLEMS = ROOT / "problems" / "robust-arm"
CLASSES = {
    "p01": "obstruction", "p02": "obstruction",
    "p03": "narrow passage", "p04": "narrow passage",
    "p05": "tight packing", "p06": "tight packing",
    "p07": "side grasp", "p08": "side grasp",
    "p09": "push", "p10": "push",
    "p11": "stacking contact", "p12": "stacking contact",
}
TIME_LIMIT = 120
SKELETONS = 1000  # so that the time limit, not the default 20 skeletons, ends a search


def test_every_problem_has_a_class():
    assert sorted(p.stem for p in PROBLEMS.glob("p*.pddl")) == sorted(CLASSES)


@pytest.mark.parametrize("name", sorted(CLASSES))
def test_check_accepts(cli, name):
    run = cli("check", DOMAIN, PROBLEMS / f"{name}.pddl", "--quiet")
    assert run.code == 0, run.out + run.err


def _message(run) -> str:
    """The solver's own words on the outcome (its last report line)."""
    lines = [ln for ln in (run.err + run.out).splitlines()
             if ln.strip() and not ln.startswith(("solution:", "time:", "skeleton #"))]
    return lines[-1].strip() if lines else f"exit {run.code}"


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(CLASSES))
def test_solve(cli, name, tmp_path):
    problem = PROBLEMS / f"{name}.pddl"
    out = tmp_path / "solution.json"
    start = time.monotonic()
    run = cli("solve", DOMAIN, problem, "--time-limit", TIME_LIMIT, "-k", SKELETONS,
              "--out", out)
    seconds = time.monotonic() - start
    solved = run.code == 0
    valid = violations = None
    if solved:
        check = cli("validate", DOMAIN, problem, out)
        valid = check.code == 0
        violations = [str(v) for v in check_solution(out, problem.with_suffix(".scene.toml"),
                                                     problem)]
    report = (f"{name} ({CLASSES[name]}): solve exit {run.code} in {seconds:.1f} s; "
              f"validate {'-' if valid is None else valid}; "
              f"checker {'-' if violations is None else violations or 'valid'}; "
              f"{_message(run) if not solved else 'plan: ' + ' '.join(_plan(run))}")
    print("ROBUST", report)
    assert solved and valid and not violations, report


def _plan(run) -> list[str]:
    return [ln.strip() for ln in run.out.splitlines() if ln.startswith("(")]
