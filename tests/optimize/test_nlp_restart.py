"""When solve_nlp restarts SLSQP: from the merit's best point, when it is nearly
feasible and clearly cheaper than the best feasible point (or none is feasible)."""

import numpy as np

from tampcli.optimize.layout import Layout
from tampcli.optimize.nlp import (
    FEASIBILITY,
    RESTART_VIOLATION,
    STALL_PENALTY,
    BestPoint,
    _Evaluator,
    _worth_restart,
)
from tampcli.optimize.stages import Rows


def _best(feasible_cost, merit_cost, merit_violation):
    ev = _Evaluator(lambda x: Rows(), Layout((("x", 1),)))
    best = BestPoint(ev, np.zeros(1))
    best.key = (0.0, feasible_cost) if feasible_cost is not None else (1.0, 5.0)
    best.merit_violation = merit_violation
    best.merit = merit_cost + STALL_PENALTY * max(merit_violation - FEASIBILITY, 0.0)
    return best


def test_a_cheap_nearly_feasible_point_beside_a_dear_feasible_one_is_worth_a_restart():
    assert _worth_restart(_best(1.30, 0.31, 2e-3))  # arm-kitchen's keyframes


def test_no_restart_far_from_feasible_or_for_a_small_saving_or_at_the_best_point():
    assert not _worth_restart(_best(1.30, 0.31, 10 * RESTART_VIOLATION))
    assert not _worth_restart(_best(0.32, 0.31, 2e-3))  # under 5 % cheaper
    assert not _worth_restart(_best(0.32, 0.32, 0.0))  # the merit's best is feasible


def test_a_nearly_feasible_point_is_worth_a_restart_when_nothing_is_feasible():
    assert _worth_restart(_best(None, 0.8, 8e-4))  # blind2 p07's tilted hand
