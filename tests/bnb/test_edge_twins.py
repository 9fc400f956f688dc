"""blind35's unsolvable twins, each a few millimetres or degrees beyond a documented
limit: refused with a proof, in about a second, no NLP solved, the reason saying
why with the figures (blind35 DOC_GAPS 1, 5, 6)."""

from __future__ import annotations

from pathlib import Path

import pytest

from tampcli.bnb import BnBOptions
from tampcli.pipeline import InputPaths, SolveOptions
from tampcli.pipeline import solve as solve_paths

SET = Path(__file__).resolve().parents[2] / "problems" / "blind35"


@pytest.mark.parametrize("stem, words", [
    ("p02", "8.3 cm wide; the gripper opens 8.692 cm and takes at most 8.192 cm"),
    ("p04", "bar (12.0 x 2.0 cm) does not fit region pad (9.7 x 9.7 cm) at any yaw"),
    ("p06", "crate moved before (push crate crate-home dock) (no face's friction cone "
            "leads from crate's start into dock)"),
])
def test_the_twin_beyond_the_limit_is_proved_unsolvable_and_says_why(stem, words):
    folder = SET / stem
    solution = solve_paths(InputPaths(str(folder / "domain.pddl"), str(folder / f"{stem}.pddl")),
                           SolveOptions(BnBOptions(time_limit=60)))
    assert solution.status == "unsolvable"
    assert words in solution.reason
    assert solution.stats["nlp_solves"] == 0
