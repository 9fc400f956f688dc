"""A motion blocked by a body the skeleton never moved names that body
(relocate.in_the_way, motion._blocked): blind15 p06, a crate in the only corridor,
failed naming the wall beside it, and the search learned nothing from it."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.optimize import relocate
from tampcli.optimize.assemble import MotionContext
from tampcli.optimize.blockers import blocker_of
from tampcli.optimize.modes import load_modes
from tampcli.optimize.motion import _blocked
from tampcli.optimize.nlp import NlpOutcome
from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.problem import lower
from tampcli.optimize.run import Run
from tampcli.pddl import parser
from tampcli.search.learned import Blocker

from .helpers import ops

P06 = Path(__file__).resolve().parents[2] / "problems" / "blind15" / "p06"


@pytest.fixture(scope="module")
def corridor():
    domain = parser.parse_domain_file(P06 / "domain.pddl")
    problem = parser.parse_problem_file(P06 / "p06.pddl")
    scene = load_scene(P06 / "p06.scene.toml", domain, problem)
    modes = load_modes(P06 / "modes.toml", domain)
    with World(scene, visuals=False) as world:
        lowered = lower(ops("(pick box box-home)", "(place box east-goal)"), scene, modes,
                        world, OptimizeOptions(time_limit=60.0), domain=domain,
                        checker=CollisionChecker(world))
        yield Run(lowered, "path")


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
