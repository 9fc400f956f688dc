"""`--force` and `--forbid`: the task restricted to plans that contain (leave out) chosen
ground actions, for `plan` and both methods of `solve`."""

from __future__ import annotations

from pathlib import Path

import pytest

from tampcli.errors import InputError
from tampcli.pddl import parser
from tampcli.search.heuristics import HFF
from tampcli.search.searches import astar
from tampcli.task.ground import ground
from tampcli.task.restrict import restrict
from tests.task.tasks import replay

ROOT = Path(__file__).resolve().parents[2]
DOMAIN = ROOT / "domains" / "gripper" / "domain.pddl"
P01 = ROOT / "problems" / "gripper" / "p01.pddl"


@pytest.fixture(scope="module")
def task():
    return ground(parser.parse_domain_file(DOMAIN), parser.parse_problem_file(P01))


def _plan(task):
    return astar(task, HFF(task)).plan


def _names(plan):
    return [op.name for op in plan]


def test_a_forced_action_is_in_every_plan_and_the_plan_holds_in_the_original_task(task):
    cheapest = _plan(task)
    assert "(move roomb rooma)" not in _names(cheapest)
    forced = _plan(restrict(task, ["( MOVE roomb  rooma)"]))
    assert "(move roomb rooma)" in _names(forced)
    originals = {op.name: op for op in task.operators}
    state = replay(task, [originals[n] for n in _names(forced)])
    assert task.goal.holds(task.closure(state))
    assert len(forced) > len(cheapest)


def test_a_forbidden_action_is_in_no_plan(task):
    first = _names(_plan(task))[0]
    plan = _names(_plan(restrict(task, forbidden=[first])))
    assert first not in plan and plan


def test_an_unknown_or_contradictory_choice_is_an_input_error(task):
    with pytest.raises(InputError, match="'\\(move rooma roomc\\)' is not a ground action") as err:
        restrict(task, ["(move rooma roomc)"])
    assert err.value.key == "--force"
    with pytest.raises(InputError, match="both forced and forbidden"):
        restrict(task, ["(move rooma roomb)"], ["(move rooma roomb)"])


def test_plan_and_solve_take_the_flags(cli):
    out = cli("plan", DOMAIN, P01, "--force", "(move roomb rooma)")
    assert out.code == 0 and "(move roomb rooma)" in out.out
    out = cli("solve", DOMAIN, P01, "--force", "(move roomb rooma)")  # a symbolic solve
    assert out.code == 0 and "(move roomb rooma)" in out.out
    out = cli("solve", DOMAIN, P01, "--forbid", "(move rooma roomc)")
    assert out.code == 2 and "--forbid" in out.err and "not a ground action" in out.err
