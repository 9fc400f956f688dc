"""Initial guesses: placements, IK keyframes, and via points for the paths.

Measured here: from a trivial initial guess SLSQP ran 37-177 s and failed on a
pick-place over a wall; from IK keyframes plus via points it converged in
under a second. So every keyframe starts at an IK solution of the tool pose
the action implies (each kind's `guess`), and every path first lifts above
what lies between.
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.optimize import final_starts
from tampcli.optimize.bodies import pose_matrix
from tampcli.optimize.grips import Grip
from tampcli.optimize.problem import TrajectoryProblem
from tampcli.optimize.values import GripChoice, Keyframes
from tampcli.optimize.world_state import grip_of


def final_guess(problem: TrajectoryProblem):
    """(placements, origins) of the final NLP's first start (final_starts.starts):
    a values.Placement per placing step (by step index), and the (x, y) point each
    is pulled towards."""
    return final_starts.starts(problem)[0](problem)


class GuessWalk:
    """The forward walk of the keyframe guess: configurations so far, object poses."""

    IK_TOLERANCE = 1e-3
    QUARTERS = (0.0, 0.5 * math.pi, math.pi, -0.5 * math.pi)

    def __init__(self, problem: TrajectoryProblem, placements, start, rng, jitter: float,
                 graded: bool = False):
        self.problem = problem
        self.world = problem.world
        self.planar = problem.planar
        self.placements = placements  # step index -> values.Placement
        self.rng = rng
        self.jitter = jitter
        # The planar place's faces ranked by how deep within the margin the disk would
        # stand, to the millimetre (kinds/place.py): the keyframe stage's last try.
        self.graded = graded
        self.q: dict[int, np.ndarray] = {}  # keyframe -> configuration
        self.grip: dict[int, float] = {}  # step -> grip parameter
        self.choices: dict[int, GripChoice] = {}
        self.poses = {n: pose_matrix(*i.pose) for n, i in problem.bodies.items() if not i.fixed}
        self.q_prev = np.asarray(start, dtype=float)

    def grip_of(self, step) -> Grip:
        return grip_of(self.problem, step, self.choices)

    def solve_ik(self, target):
        seed, rng_seed = self._ik_seeds()
        return self.world.ik(target, seed=seed, rng_seed=rng_seed)

    def solve_ik_many(self, targets) -> list:
        """[`solve_ik` of each target in turn]: the same random draws, in the same
        order, and the same answers; the IK solved as one batch (World.ik_many)."""
        seeds, rng_seeds = zip(*(self._ik_seeds() for _ in targets), strict=True) \
            if targets else ((), ())
        return self.world.ik_many(targets, seeds, rng_seeds)

    def _ik_seeds(self) -> tuple[np.ndarray, int]:
        """(IK seed, rng seed) of the next question: q_prev, jittered on a retry."""
        world = self.world
        seed = self.q_prev + self.rng.normal(0.0, self.jitter, len(self.q_prev)) \
            if self.jitter else self.q_prev
        return np.clip(seed, world.lower, world.upper), int(self.rng.integers(1 << 30))

    def best_of(self, targets, held=None, ignore=frozenset()):
        """IK for each (target, tag): reachable first, then the least deep within the
        margin (to the millimetre: a hand 6 mm from a post beats one 3 cm into it, though
        both are within the 1 cm margin; blind2 p01), then closest to q_prev."""
        best = None
        moved = {n: t for n, t in self.poses.items() if n not in (held or ("",))[0:1]}
        answers = self.solve_ik_many([target for target, _ in targets])
        for (_, tag), (q, res) in zip(targets, answers, strict=True):
            clash = round(self.clash(q, moved, held, ignore), 3) if len(targets) > 1 else 0.0
            score = (res > self.IK_TOLERANCE, clash, float(np.linalg.norm(q - self.q_prev)))
            if best is None or score < best[0]:
                best = (score, q, tag)
        return best[1], best[2]

    def clash(self, q, moved, held=None, ignore=frozenset()) -> float:
        """How far (m) within the margin of anything (`moved`: bodies off their start
        pose) the arm at q, and what it holds, are: 0 when clear or with no checker."""
        checker, margin = self.problem.checker, self.problem.options.margin
        if checker is None:
            return 0.0
        d = checker.min_distance(q, moved, held, frozenset(ignore), static=False,
                                 horizon=margin)
        return max(0.0, margin - d)

    def clashes(self, qs, moved, ignores) -> list[float]:
        """`clash` of each of the configurations qs (nothing held), each with its own
        ignored names, in one batched query: the same answers, row by row."""
        checker, margin = self.problem.checker, self.problem.options.margin
        if checker is None or not len(qs):
            return [0.0] * len(qs)
        found = checker.distances_many(np.array(qs), moved, None,
                                       [frozenset(i) for i in ignores], margin, static=False)
        return [max(0.0, margin - min((c.distance for c in cs), default=math.inf))
                for cs in found]

    @staticmethod
    def angle(v) -> float:
        return float(math.atan2(v[1], v[0]))

    @staticmethod
    def planar_q(obj_pos, grip: Grip, phi: float) -> np.ndarray:
        c, _, _, _ = grip.parts(phi)
        return np.asarray(obj_pos[:2], dtype=float) - c[:2]


def keyframe_guess(problem: TrajectoryProblem, placements, start, rng,
                   jitter: float = 0.0, graded: bool = False
                   ) -> tuple[Keyframes, dict[int, GripChoice]]:
    """IK keyframes following the actions; returns (keyframes, discrete grip choices).

    `placements`: step index -> values.Placement. `jitter` (rad) perturbs the
    IK seeds: a retry then lands in another IK branch.
    """
    walk = GuessWalk(problem, placements, start, rng, jitter, graded)
    for step in problem.steps:
        step.kind.guess(walk, step)
    if not problem.planar:
        keyframe_step = {k: step for step in problem.steps for k in step.keyframes}
        for k in range(problem.n_keyframes - 2, -1, -1):
            step = keyframe_step.get(k)
            if step is not None:
                step.kind.reseed(walk, step, k)
    return (Keyframes(tuple(walk.q[k] for k in range(problem.n_keyframes)),
                      {s: walk.grip[s] for s in problem.grip_params}), walk.choices)

