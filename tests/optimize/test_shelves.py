"""Several objects into one region where a row along its long side does not fit: the
final stage starts from shelves (final_starts.shelved), and the planar robot puts
each one down from the face where it stands clearest (kinds/place.py)."""

from __future__ import annotations

import itertools
from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize import final_starts
from tampcli.optimize.solve import solve

from .helpers import lowered_folder, ops, path_from_keyframes

POCKET = Path(__file__).resolve().parents[2] / "problems" / "blind27" / "p05"
# blind27 p05: a slab (8 x 14 cm) and two boxes (6 x 7 cm) fill a 14.6 cm square pocket
# walled on its north, east and south sides; the robot comes from the west.
SLAB_FIRST = ("(grab slab home-s)", "(release slab pocket)", "(grab p home-p)",
              "(release p pocket)", "(grab q home-q)", "(release q pocket)")
BOXES_FIRST = ("(grab p home-p)", "(release p pocket)", "(grab q home-q)",
               "(release q pocket)", "(grab slab home-s)", "(release slab pocket)")


def _footprints(problem, result):
    out = {}
    for i, p in result.placements.items():
        info = problem.bodies[problem.steps[i].obj]
        out[problem.steps[i].obj] = (p.x - info.half[0], p.x + info.half[0],
                                     p.y - info.half[1], p.y + info.half[1])
    return out


@pytest.mark.parametrize("skeleton", [SLAB_FIRST, BOXES_FIRST], ids=["slab-first",
                                                                      "boxes-first"])
def test_a_pocket_is_filled_in_two_columns_the_first_put_down_farthest(skeleton):
    with lowered_folder(POCKET, "p05", ops(*skeleton)) as problem:
        assert final_starts.starts(problem)[0] is final_starts.shelved
        final = solve(problem, "final")
        assert final.solved, final.worst_constraint
        feet = _footprints(problem, final)
        for a, b in itertools.combinations(feet, 2):
            fa, fb = feet[a], feet[b]
            apart = fa[1] <= fb[0] or fb[1] <= fa[0] or fa[3] <= fb[2] or fb[3] <= fa[2]
            assert apart, (a, b, fa, fb)
        first = problem.steps[1].obj
        assert feet[first][1] > 0.86  # against the east wall (inner face at 0.873)
        # the slack shared: nothing left against a wall at the 1 mm gap alone
        assert min(f[2] for f in feet.values()) > -0.073 + 0.0015
        assert max(f[3] for f in feet.values()) < 0.073 - 0.0015


def test_shelves_start_with_equal_gaps_and_need_not_fit():
    with lowered_folder(POCKET, "p05", ops(*SLAB_FIRST)) as problem:
        placements, _ = final_starts.shelved(problem)
        slab, p, q = (placements[i] for i in (1, 3, 5))
        # depth (x): 14.6 cm less 8 + 6 cm leaves 2 mm per gap; sideways (y) for p and q
        # 14.6 less 14 cm: 2 mm per gap
        assert slab.x == pytest.approx(0.873 - 0.002 - 0.04)
        assert p.x == pytest.approx(0.727 + 0.002 + 0.03)
        assert q.x == pytest.approx(p.x)
        assert sorted([p.y, q.y]) == pytest.approx([-0.073 + 0.002 + 0.035,
                                                    0.073 - 0.002 - 0.035])
    # p, slab, q: the slab closes p's shelf, q finds no room: the packed row instead
    order = ("(grab p home-p)", "(release p pocket)", "(grab slab home-s)",
             "(release slab pocket)", "(grab q home-q)", "(release q pocket)")
    with lowered_folder(POCKET, "p05", ops(*order)) as problem:
        shelves, _ = final_starts.shelved(problem)
        row, _ = final_starts.packed(problem)
        assert all(np.isclose(shelves[i].x, row[i].x) and np.isclose(shelves[i].y, row[i].y)
                   for i in row)


@pytest.mark.parametrize("skeleton", [SLAB_FIRST, BOXES_FIRST], ids=["slab-first",
                                                                      "boxes-first"])
def test_the_disk_puts_each_piece_down_from_the_open_side(skeleton):
    """Before: near the walls every face of a box was within the 1 cm margin at the
    place, so the guess kept the face its grasp chose (east, for a box taken after the
    slab was in), the disk inside the slab: 'collision planar_body vs slab by 4.1 cm'."""
    with lowered_folder(POCKET, "p05", ops(*skeleton)) as problem:
        path = path_from_keyframes(problem)
        assert path.solved, path.worst_constraint
