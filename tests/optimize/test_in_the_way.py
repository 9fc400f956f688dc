"""A motion blocked by a body the skeleton never moved names that body
(relocate.in_the_way, motion._blocked): blind15 p06, a crate in the only corridor,
failed naming the wall beside it, and the search learned nothing from it."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize import relocate
from tampcli.optimize.assemble import MotionContext
from tampcli.optimize.blockers import blocker_of
from tampcli.optimize.motion import _blocked
from tampcli.optimize.nlp import NlpOutcome
from tampcli.optimize.run import Run
from tampcli.search.learned import Blocker

from .helpers import lowered_folder, ops

P06 = Path(__file__).resolve().parents[2] / "problems" / "blind15" / "p06"


@pytest.fixture(scope="module")
def corridor():
    skeleton = ops("(pick box box-home)", "(place box east-goal)")
    with lowered_folder(P06, "p06", skeleton) as problem:
        yield Run(problem, "path")


def _through(moved=None):
    """The disk from its start, west of the wall, to the east room: motion 0."""
    return MotionContext(0, np.array([0.10, 0.30]), np.array([1.20, 0.30]), None, None,
                         moved or {}, None)


def test_the_crate_in_the_corridor_is_in_the_way_of_the_disk(corridor):
    run = corridor
    assert relocate.in_the_way(run, _through(), run.sampling(0.25)) == \
        (("crate", "link:planar_body"),)


def test_nothing_is_in_the_way_once_the_crate_is_moved_out(corridor):
    run = corridor
    crate = np.eye(4)
    crate[:3, 3] = (1.05, 0.0, 0.025)  # pushed on into the east bay
    assert relocate.in_the_way(run, _through({"crate": crate}), run.sampling(0.25)) == ()


def test_the_failure_names_the_crate_and_teaches_to_move_it_first():
    failed = NlpOutcome(np.zeros(2), "infeasible", 1.0, 0.06,
                        "motion 1 before (place box east-goal): collision planar_body vs "
                        "wall-s (margin 1 mm) by 6.1 cm", 30, None, "stalled")
    out = _blocked(failed, "motion 1 before (place box east-goal)",
                   (("crate", "link:planar_body"), ("box", "held:box")))
    assert out.status == "infeasible"
    assert out.worst.startswith("motion 1 before (place box east-goal): collision "
                                "planar_body vs crate (and box)")
    assert blocker_of(out.worst, frozenset({"crate", "box"})) == \
        Blocker("crate", "(place box east-goal)")
    # The wall's row taught nothing.
    assert blocker_of(failed.worst, frozenset({"crate", "box"})) is None
