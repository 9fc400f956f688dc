"""Options of the trajectory optimizer (one frozen value, checked when built)."""

from __future__ import annotations

from dataclasses import dataclass

from tampcli.errors import OptionError, require_int, require_number
from tampcli.optimize.backends import BACKENDS


@dataclass(frozen=True)
class OptimizeOptions:
    """How a fixed skeleton is lowered to an NLP and solved.

    waypoints: waypoints per motion phase (T, a count >= 2); the keyframe of an
        action is the last one.
    margin: clearance (m) the optimizer keeps between moving parts and the world;
        `verify` accepts anything not penetrating, so the margin is slack for it.
    tight_margin: the clearance (m) an NLP is solved again with where `margin` made it
        infeasible (a passage narrower than twice the margin): the margin never turns a
        feasible problem infeasible, it shrinks where the geometry needs it.
    sampling_checks: validity checks a motion's sampling-based planner (RRT-Connect
        over the collision model) may make when the interpolated and via-point starts
        fail (a count, not seconds, so that the same input and seed give the same
        result however loaded the machine is; about 4,000 a second here).
    activation: distance (m) under which a pair enters the constraints; pairs further
        apart contribute a constant row (the vector keeps a fixed size per SLSQP call).
    max_iterations: SLSQP iterations per NLP solve (a count).
    time_limit: wall seconds per `solve` call (all NLPs of one stage together).
    interpolation_checks: collision sample points between consecutive waypoints
        (constraints only at waypoints let an arm pass through a thin wall between them).
    seed: seed of the random perturbations (IK restarts, symmetry breaking): the same
        input and seed give the same result.
    nlp: the solver of the path stage's NLPs, a name in backends.BACKENDS: "slsqp",
        "ipopt" (cyipopt, an optional extra), or "auto" (Ipopt for the large ones
        where it is installed; the final and keyframe NLPs are SLSQP's).
    """

    waypoints: int = 10
    margin: float = 0.01
    tight_margin: float = 0.001
    sampling_checks: int = 32000
    activation: float = 0.05
    max_iterations: int = 200
    time_limit: float = 30.0
    interpolation_checks: int = 3
    seed: int = 0
    nlp: str = "auto"

    def __post_init__(self):
        require_int(self.waypoints, "waypoints", 2)
        require_number(self.margin, "margin", unit="m")
        require_number(self.tight_margin, "tight_margin", unit="m")
        if self.tight_margin > self.margin:
            raise OptionError("tight_margin", f"must not exceed margin ({self.margin} m), "
                              f"got {self.tight_margin!r}")
        require_int(self.sampling_checks, "sampling_checks", 1)
        require_number(self.activation, "activation", unit="m")
        if not self.activation > self.margin:
            raise OptionError("activation", f"must exceed margin ({self.margin} m), "
                              f"got {self.activation!r}")
        require_int(self.max_iterations, "max_iterations", 1)
        require_number(self.time_limit, "time_limit", positive=True, unit="s", finite=False)
        require_int(self.interpolation_checks, "interpolation_checks", 0)
        if isinstance(self.seed, bool) or not isinstance(self.seed, int):
            raise OptionError("seed", f"must be an integer, got {self.seed!r}")
        if self.nlp not in BACKENDS:
            raise OptionError("nlp", f"must be one of {', '.join(BACKENDS)}, got {self.nlp!r}")
