"""Per-call bookkeeping of one stage solve: the deadline, the counters, the
checker and kinematics, and what a failed motion leaves for the path stage."""

from __future__ import annotations

import time

import numpy as np

from tampcli.geometry.sampled_path import SamplingOptions
from tampcli.optimize.backends import BACKENDS, Slsqp
from tampcli.optimize.grips import Kinematics
from tampcli.optimize.hand import narrowed
from tampcli.optimize.problem import TrajectoryProblem
from tampcli.optimize.result import TrajectoryResult


class Run:
    """Per-call bookkeeping: deadline, counters, the checker and kinematics."""

    def __init__(self, problem: TrajectoryProblem, stage: str):
        self.problem = problem
        self.stage = stage
        self.t0 = time.perf_counter()
        self.deadline = self.t0 + problem.options.time_limit
        self.iterations = 0
        self.nlp_solves = 0
        self.kin = Kinematics(problem.world)
        self.checker = problem.checker
        self.start = np.asarray(problem.world.start, dtype=float)
        self.rng = np.random.default_rng(problem.options.seed)
        self.obstruction = None  # relocate.Obstruction of the last motion that failed
        # (body, robot part) that blocked the last motion to fail (relocate.in_the_way)
        self.in_the_way: tuple[tuple[str, str], ...] = ()
        # Whether, in that motion, the planar robot alone had no grid route either: no
        # other grip of what it holds makes room (path_stage._robot_in_the_way)
        self.blocked_alone = False
        self.anchors = None  # relocate.Relocation.anchors the keyframe NLP keeps to
        self.cutoff = None  # a trajectory cost the caller has no use for reaching (bounded)
        self.routes: dict = {}  # the planar grid routes found, by motion (motion.py)
        self.separated: set = set()  # the keys of `routes` whose grid proves no path

    def result(self, status: str, **fields) -> TrajectoryResult:
        fields.setdefault("bound_kind", "heuristic" if self.stage != "final" else "proved")
        fields.setdefault("narrowed", narrowed(self.problem.hand))
        return TrajectoryResult(status=status, stage=self.stage, names=self.problem.names,
                                iterations=self.iterations, nlp_solves=self.nlp_solves,
                                seconds=time.perf_counter() - self.t0, **fields)

    def nlp(self, evaluate, layout, x0, bounds, backend=None):
        """One counted solve by `backend` (SLSQP when None: the final and keyframe NLPs)."""
        out = (backend or Slsqp()).solve(evaluate, layout, x0, bounds,
                                         self.problem.options.max_iterations, self.deadline)
        self.iterations += out.iterations
        self.nlp_solves += 1
        return out

    def sampling(self, share: float) -> SamplingOptions:
        """A sampling query's options: `share` of the motion's budget of validity checks
        (a fifth of it for shortcutting), the tight margin as clearance, a seed drawn
        from this solve's generator, the solve's deadline."""
        opts = self.problem.options
        checks = max(1, int(share * opts.sampling_checks))
        return SamplingOptions(checks=checks, simplify_checks=min(2000, checks // 4),
                               seed=int(self.rng.integers(1, 1 << 31)), deadline=self.deadline,
                               clearance=opts.tight_margin)

    def path_nlp(self, evaluate, layout, x0, bounds):
        """A motion's NLP, by the options' backend (`nlp`)."""
        return self.nlp(evaluate, layout, x0, bounds, BACKENDS[self.problem.options.nlp])
