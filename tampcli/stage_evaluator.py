"""How branch and bound asks for a stage of a skeleton: `StageEvaluator` lowers each
skeleton once on the solve's one World (`Geometry`) and solves a stage of it within
what is left of the solve's time; it also gives the planar relaxation and the rows a
failed keyframe stage left violated. The pipeline builds one per solve, and a
skeleton_pool worker one of its own."""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # numpy, pybullet and FCL behind these
    from tampcli.geometry.collision import CollisionChecker
    from tampcli.geometry.world import World


@dataclass(frozen=True)
class Geometry:
    """The solve's one World and the CollisionChecker over it."""

    world: World
    checker: CollisionChecker


class StageEvaluator:
    """`evaluate(ops, stage, warm)` for branch and bound: lowers each skeleton once
    and solves a stage within what is left of the solve's time."""

    def __init__(self, inputs, geometry: Geometry, options,
                 deadline: float):
        from tampcli.optimize.problem import lower
        from tampcli.optimize.relaxed import relaxed_bound
        from tampcli.optimize.solve import solve as solve_stage

        self.inputs, self.geometry, self.deadline = inputs, geometry, deadline
        self.options = options.optimize
        self.lower, self.solve_stage, self.relaxed_bound = lower, solve_stage, relaxed_bound
        self.lowered: dict[tuple[str, ...], object] = {}

    def _lowered(self, ops):
        names = tuple(op.name for op in ops)
        if names not in self.lowered:
            self.lowered[names] = self.lower(
                ops, self.inputs.scene, self.inputs.modes, self.geometry.world, self.options,
                domain=self.inputs.domain, checker=self.geometry.checker)
        return self.lowered[names]

    def __call__(self, ops, stage, warm, cutoff=None):
        remaining = max(self.deadline - time.perf_counter(), 0.5)
        options = self.options if remaining >= self.options.time_limit else \
            dataclasses.replace(self.options, time_limit=remaining)
        return self.solve_stage(self._lowered(ops), stage, warm=warm, options=options,
                                cutoff=cutoff)

    def relaxed(self, ops):
        """The prefix's relaxed bound (optimize/relaxed.py), None off the planar robot."""
        return self.relaxed_bound(self._lowered(ops))

    def rows(self, result) -> tuple:
        """bnb/violations.violated_rows of a failed keyframe result of a skeleton this
        evaluator lowered (() otherwise: another stage, or a worker's skeleton)."""
        problem = self.lowered.get(tuple(result.names))
        if problem is None or result.stage != "keyframes" or result.solved:
            return ()
        return self._violated_rows(problem, result)

    def violated(self, ops, result) -> str | None:
        """The rows a failed keyframe stage left violated, by action (bnb/violations.py)."""
        from tampcli.bnb.violations import by_action

        rows = self._violated_rows(self._lowered(ops), result)
        return by_action(rows, tuple(op.name for op in ops))

    def _violated_rows(self, problem, result) -> tuple:
        from tampcli.bnb.violations import violated_rows
        from tampcli.optimize.grips import Kinematics

        return violated_rows(problem, result, Kinematics(self.geometry.world))
