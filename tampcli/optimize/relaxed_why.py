"""Why a planar relaxation (relaxed.py) is infeasible, in words: the part that alone
makes it so, worded as the NLPs word it where the skeleton source learns from it."""

from __future__ import annotations

import math

from tampcli.optimize.convex_qp import solve_convex_qp
from tampcli.optimize.relaxed_apart import blocks_alone, solve_apart

CONE = "no pushed face's friction cone leads into the target (a drag or a pull)"


def cone_why(problem, index: int) -> str:
    """Words for a push none of whose faces' cones leads into its target: worded as
    the NLPs word it when it is the prefix's last step (the skeleton source learns
    that its object must be moved before it: from where it stands, no face leads
    there)."""
    name = problem.steps[index].name
    if name == problem.steps[-1].name:
        return f"{name}: motion not into the pushed face ({CONE})"
    return f"{CONE}: {name}"


def why_infeasible(problem, hull, budget: int, pushes: list[str], make) -> str | None:
    """The part of the relaxation that makes it infeasible, when one alone does.
    `hull`: the Builder with no face chosen (no friction cone); `pushes`: the names
    of the pushing steps (with faces to choose); `make(faces)`: the Builder of an
    assignment of faces."""
    if math.isinf(solve_convex_qp(hull.qp()).value):
        return None
    if pushes and not math.isinf(solve_apart(hull.qp(), hull.aparts, budget)[0].value):
        why = _no_face_why(problem, hull, make)
        if pushes[-1] == problem.steps[-1].name:
            # The last step of a shortest infeasible prefix is the push that fails: worded
            # as the NLPs word it, the skeleton source learns that its object must be
            # moved before it (from where it stands, no face leads there).
            return f"{pushes[-1]}: motion not into the pushed face ({why})"
        return why
    alone = next((p for p in hull.aparts if blocks_alone(p, hull.box)), None)
    if alone is not None:
        # Worded as the NLPs word an overlap: the skeleton source learns the blocker.
        return f"{alone.label} wherever it is put down"
    if hull.aparts:
        return "what is put down cannot be kept apart from what rests there"
    return None


LIMITS = ("no pushed face whose friction cone leads into the target can be pushed "
          "with the robot within its joint limits")
BODIES = ("no pushed face whose friction cone leads into the target can be pushed "
          "clear of the bodies there")


def _no_face_why(problem, hull, make) -> str:
    """Why no face of the last push does, every face's QP being infeasible and the QP
    with no face chosen feasible: its cone (no face leads into the target), the joint
    limits (one does, but the robot cannot stand at it: blind20 p03, a crate 1 cm from
    the bench's edge, pushed away from it), or the bodies there."""
    step = next(s for s in reversed(problem.steps) if s.kind.relax_faces(problem, s))
    faces = hull.open_faces(step, step.kind.relax_faces(problem, step))
    if not faces:
        return CONE
    if all(math.isinf(solve_convex_qp(make({step.index: f}).qp()).value)
           for f in faces):
        return LIMITS
    return BODIES
