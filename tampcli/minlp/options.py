"""Options of the time-indexed MINLP (`solve --method minlp`)."""

from __future__ import annotations

from dataclasses import dataclass

from tampcli.bnb import BnBOptions

COLLISION_MODELS = ("outer", "inner")


@dataclass(frozen=True)
class MinlpOptions:
    """What `solve_minlp` builds and how long SCIP may work on it.

    steps: T, the motion steps; the trajectory has T + 1 waypoints and every
        action happens at one of waypoints 1..T.
    time_limit: CPU seconds SCIP may spend (its own clock; model building not counted):
        on a shared machine the wall time is longer, the search the same.
    symbolic_weight: w in objective = trajectory cost + w * symbolic cost, as branch and bound.
    gap: SCIP stops when (primal - dual) / |primal| falls to this (0.0001 is SCIP's default).
    polygon_sides: a round footprint (the robot's disk, a cylinder) becomes a regular polygon
        with this many sides (even, >= 4) in the collision constraints.
    collision_model: "outer": the polygon circumscribes the circle, so every solution is
        collision-free but SCIP's bound holds for that (more constrained) model only;
        "inner": the polygon is inscribed, a relaxation whose bound holds for the true disks,
        but whose solutions may graze a round body.
    warm_start: a solution.json (e.g. from branch and bound) given to SCIP as a partial
        solution to complete.
    schedule: a solution.json whose actions (and push starts) are fixed at its waypoints,
        scaled to T: only the trajectory for that sequence of decisions is left, the
        lesson's V(d) of §2, solved globally (e.g. branch and bound's skeleton and its
        waypoints per motion).
    forced: ground action names that must each appear in the plan (e.g. to optimize one
        skeleton of the lesson's push-versus-pick comparison).
    forbidden: ground action names that must not appear.
    seed: SCIP's random seed.
    """

    steps: int = 8
    time_limit: float = 120.0
    symbolic_weight: float = BnBOptions.symbolic_weight  # the one default, bnb's
    gap: float = 1e-4
    polygon_sides: int = 16
    collision_model: str = "outer"
    warm_start: str | None = None
    schedule: str | None = None
    forced: tuple[str, ...] = ()
    forbidden: tuple[str, ...] = ()
    seed: int = 0

    def __post_init__(self):
        if self.steps < 1:
            raise ValueError("steps must be >= 1")
        if self.time_limit <= 0:
            raise ValueError("time_limit must be > 0")
        if self.symbolic_weight < 0:
            raise ValueError("symbolic_weight must be >= 0")
        if self.polygon_sides < 4 or self.polygon_sides % 2:
            raise ValueError("polygon_sides must be even and >= 4")
        if self.collision_model not in COLLISION_MODELS:
            raise ValueError(f"collision_model must be one of {', '.join(COLLISION_MODELS)}")
