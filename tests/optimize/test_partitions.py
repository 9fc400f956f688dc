"""A planar carry round several partitions solves from its first start.

The class of gen1 planar-s02: the disk carries a block round two partition walls
(motions of several metres, the straight line through both walls). Its path
NLP failed from the via-point start (bent round the first body only), and from
RRT-Connect's path (grazing each wall's end, on 10 segments 30 cm long) SLSQP
pulled the segments taut across the walls' ends between the waypoints, where no
row held them. The scenes (tests/optimize/scenes/partitions): two doorways in
two partitions, two staggered partitions with a post at a turn, a doorway with
a post just beyond it. Before the grid route (geometry/planar_route.py) the
path stage took 5, 22 and 8 NLP solves, and staggered 13.7 s.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize.solve import solve
from tampcli.optimize.verify import verify

from .helpers import lowered_folder, ops

SCENES = Path(__file__).resolve().parent / "scenes" / "partitions"
CARRY = ops("(pick crate home)", "(place crate goal)")


@pytest.mark.parametrize("stem", ["two-doors", "staggered", "door-post"])
def test_the_carry_round_the_partitions_solves_at_once(stem):
    with lowered_folder(SCENES, stem, CARRY) as problem:
        keyframes = solve(problem, "keyframes")
        assert keyframes.solved, keyframes.worst_constraint
        path = solve(problem, "path", keyframes)
        assert path.solved, path.worst_constraint
        assert verify(problem, path, factor=10) == []
        # The first start of each motion solves: no sampled path, no other grip.
        assert path.nlp_solves <= 4
        # The carry (the motion with the crate attached) is a detour on short steps:
        # no two waypoints further apart than the disk is wide.
        carry = next(p for p in path.phases if p.attached == "crate" and p.action is None)
        span = path.trajectory[carry.start:carry.end + 1]
        assert len(span) > 12
        assert np.linalg.norm(np.diff(span, axis=0), axis=1).max() <= 2 * \
            problem.scene.robot.radius


def test_tampcli_solves_the_staggered_carry_and_its_answer_validates(cli, tmp_path):
    domain, problem = SCENES / "domain.pddl", SCENES / "staggered.pddl"
    out = tmp_path / "solution.json"
    solved = cli("solve", "--quiet", "--first", "--time-limit", "60", "--out", out, domain,
                 problem)
    assert solved.code == 0, solved.err
    assert json.loads(out.read_text())["plan"] == ["(pick crate home)", "(place crate goal)"]
    checked = cli("validate", "--json", domain, problem, out)
    assert checked.code == 0, checked.out
