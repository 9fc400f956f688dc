"""The keyframe NLP's rows between the arm and the supports its places set objects
down on, asked for only where a solved keyframe needs them.

A place's keyframe has no rows for its support (the object rests on it), so an arm's
link can pass through the support unseen: blind34 p01, a block put down under a low
hood, its keyframe solved with the Panda's forearm 2.2 cm inside the table, which only
the path stage's check at 10x found. `into_support` looks (one evaluation of the rows
with the supports in), `with_supports` solves the keyframe NLP again with them.
"""

from __future__ import annotations

import time

import numpy as np

from tampcli.optimize.nlp import FEASIBILITY
from tampcli.optimize.run import Run
from tampcli.optimize.stages import keyframe_rows


def into_support(run: Run, layout, out, choices, at, checker) -> bool:
    """Whether, at the solved keyframes `out`, an arm's link is nearer than the tight
    margin (less FEASIBILITY) to the support a place sets its object down on: the
    keyframe NLP leaves a place's support out of its rows (the object rests on it),
    and a link can go through it unseen (blind34 p01). One evaluation of the rows
    with the supports in (stages.KeyframeWalk.collide)."""
    supports = {s.name: s.support for s in at.steps if s.kind.places and s.support}
    if at.planar or not supports:
        return False
    rows = keyframe_rows(at, layout.unpack(out.x), choices, run.kin, checker, run.start,
                         anchors=run.anchors, supports=True)
    values = np.concatenate(rows.ineq.values) if rows.ineq.values else np.zeros(0)
    return any(value < -FEASIBILITY and label.step in supports
               and f" vs {supports[label.step]} (" in label.what
               for label, value in zip(rows.ineq.labels, values, strict=True))


def with_supports(run: Run, layout, bounds, out, choices, at, checker):
    """The keyframe NLP again from `out` with the rows between the arm and the places'
    supports (the tight margin), at the margin, then at the tight margin; the last
    outcome where neither solves: the keyframes went through a support, a failure.
    Only where needed (`into_support`): with those rows in every keyframe NLP, the
    answers of tight racks moved a little, and two lost `validate --physics`
    (blind27 p06, blind31 p01)."""
    again = out
    for margin in dict.fromkeys((at.options.margin, at.options.tight_margin)):
        problem = at.at_margin(margin)

        def evaluate(x, problem=problem):
            return keyframe_rows(problem, layout.unpack(x), choices, run.kin, checker,
                                 run.start, anchors=run.anchors, supports=True)

        again = run.nlp(evaluate, layout, out.x, bounds)
        if again.status == "solved" or time.perf_counter() > run.deadline:
            return again
    return again
