"""Options of the trajectory optimizer (one frozen value, checked when built)."""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class OptimizeOptions:
    """How a fixed skeleton is lowered to an NLP and solved.

    waypoints: waypoints per motion phase (T); the keyframe of an action is the last one.
    margin: clearance (m) the optimizer keeps between moving parts and the world;
        `verify` accepts anything not penetrating, so the margin is slack for it.
    activation: distance (m) under which a pair enters the constraints; pairs further
        apart contribute a constant row (the vector keeps a fixed size per SLSQP call).
    max_iterations: SLSQP iterations per NLP solve.
    time_limit: wall seconds per `solve` call (all NLPs of one stage together).
    interpolation_checks: collision sample points between consecutive waypoints
        (constraints only at waypoints let an arm pass through a thin wall between them).
    seed: seed of the random perturbations (IK restarts, symmetry breaking).
    """

    waypoints: int = 10
    margin: float = 0.01
    activation: float = 0.05
    max_iterations: int = 200
    time_limit: float = 30.0
    interpolation_checks: int = 3
    seed: int = 0

    def __post_init__(self):
        if not isinstance(self.waypoints, int) or self.waypoints < 2:
            raise ValueError(f"waypoints must be an integer >= 2, got {self.waypoints!r}")
        if not (math.isfinite(self.margin) and self.margin >= 0):
            raise ValueError(f"margin must be >= 0 (m), got {self.margin!r}")
        if not (math.isfinite(self.activation) and self.activation > self.margin):
            raise ValueError(f"activation must exceed margin ({self.margin} m), "
                             f"got {self.activation!r}")
        if not isinstance(self.max_iterations, int) or self.max_iterations < 1:
            raise ValueError(f"max_iterations must be an integer >= 1, got "
                             f"{self.max_iterations!r}")
        if not self.time_limit > 0:
            raise ValueError(f"time_limit must be > 0 (s), got {self.time_limit!r}")
        if not isinstance(self.interpolation_checks, int) or self.interpolation_checks < 0:
            raise ValueError("interpolation_checks must be an integer >= 0, got "
                             f"{self.interpolation_checks!r}")
        if not isinstance(self.seed, int):
            raise ValueError(f"seed must be an integer, got {self.seed!r}")
