"""`check` and `plan` read PDDL through one front end: each accepts exactly what
the other accepts, with the same warnings and the same errors."""

import json
from pathlib import Path

import pytest

from tests.pddl import ipc

HERE = Path(__file__).resolve().parent
TWICE = HERE / "twice_typed" / "domain.pddl"
TWICE1 = HERE / "twice_typed" / "p01.pddl"
MALFORMED = HERE / "malformed"
BASE = MALFORMED / "base-domain.pddl"

# Every vendored IPC domain file, with the first problem that uses it.
_FIRST: dict = {}
for _domain, _problem in ipc.pairs():
    _FIRST.setdefault(_domain, (_domain, _problem))
FIRSTS = sorted(_FIRST.values())
MALFORMED_PROBLEMS = sorted(p for p in MALFORMED.glob("prob-*.pddl")
                            if p.name != "prob-as-domain.pddl")


def _front_ends(cli, domain, problem):
    """(check, plan) runs; plan stops before its first expansion: front end only."""
    return (cli("check", domain, problem, "--json"),
            cli("plan", domain, problem, "--json", "--max-expansions", "0"))


def _accepted(run) -> bool:
    return run.code != 2


@pytest.mark.parametrize("domain, problem", FIRSTS,
                         ids=[f"{p.parent.name}/{p.name}" for _, p in FIRSTS])
def test_check_accepts_exactly_what_plan_accepts_on_ipc(cli, domain, problem):
    check, plan = _front_ends(cli, domain, problem)
    assert _accepted(check) == _accepted(plan)
    assert _accepted(check), check.out
    assert json.loads(check.out)["warnings"] == []
    assert "warning" not in plan.err


def test_type_declared_twice_is_accepted_by_both_with_one_warning(cli):
    check, plan = _front_ends(cli, TWICE, TWICE1)
    assert check.code == 0, check.out
    warnings = json.loads(check.out)["warnings"]
    assert len(warnings) == 1
    assert warnings[0].startswith(f"{TWICE}:8:11: type bay is declared again (first on line 6)")
    assert "subtype of object and surface" in warnings[0]
    assert warnings[0] in plan.err
    assert json.loads(plan.out)["status"] == "limit"


def test_type_declared_twice_is_a_subtype_of_both_parents(cli):
    # `on ?x - crate ?s - surface` with a stock: only a bay that is a surface fits
    run = cli("plan", TWICE, TWICE1)
    assert run.code == 0, run.err
    assert run.out.splitlines() == ["(pick k x s1 d r)", "(put k x s2 d r)",
                                    "; cost = 2 (unit cost)"]


@pytest.mark.parametrize("problem", MALFORMED_PROBLEMS, ids=[p.name for p in MALFORMED_PROBLEMS])
def test_plan_refuses_what_check_refuses_with_the_same_error(cli, problem):
    check, plan = _front_ends(cli, BASE, problem)
    assert check.code == plan.code == 2
    assert json.loads(check.out)["error"] == json.loads(plan.out)["error"]


def test_stats_line_ends_with_a_newline(cli):
    run = cli("plan", TWICE, TWICE1)
    assert run.err.endswith("\n")
    stats = run.err.splitlines()[-1]
    assert stats.startswith("parse ") and stats.endswith(", generated 7")
    failed = cli("plan", TWICE, TWICE1, "--max-expansions", "0")
    assert failed.code == 1 and failed.err.endswith("\n")
    assert any(line.startswith("parse ") for line in failed.err.splitlines())


def test_stats_line_ends_with_a_newline_in_a_real_process():
    import subprocess
    import sys

    run = subprocess.run([sys.executable, "-m", "tampcli", "plan", str(TWICE), str(TWICE1)],
                         capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stderr
    assert run.stderr.endswith(", generated 7\n")
    assert run.stdout.endswith("; cost = 2 (unit cost)\n")


def test_a_type_declared_a_subtype_of_itself_is_warned_about(cli, tmp_path):
    """`(:types thing zone puck - thing)` (blind9's author wrote a hierarchy so):
    thing is no type of its own above the others; both front ends warn, at the
    name's place, and read it under object."""
    domain = tmp_path / "domain.pddl"
    domain.write_text("(define (domain d) (:requirements :typing)\n"
                      "  (:types thing zone puck - thing)\n"
                      "  (:predicates (at ?p - puck ?z - zone))\n"
                      "  (:action put :parameters (?p - puck ?z - zone)\n"
                      "    :precondition () :effect (at ?p ?z)))\n")
    problem = tmp_path / "p.pddl"
    problem.write_text("(define (problem p) (:domain d) (:objects p1 - puck z1 - zone)\n"
                       "  (:init) (:goal (at p1 z1)))\n")
    check, plan = _front_ends(cli, domain, problem)
    warnings = json.loads(check.out)["warnings"]
    assert len(warnings) == 1 and warnings[0].startswith(f"{domain}:2:11: type thing is ")
    assert "subtype of itself" in warnings[0] and warnings[0] in plan.err
    assert warnings[0].endswith("and zone, puck as subtypes of thing")
    assert json.loads(check.out)["domain"]["types"]["thing"] == ["object"]
    solved = cli("plan", domain, problem, "--json")
    assert json.loads(solved.out)["status"] == "solved" and "(put p1 z1)" in solved.out
