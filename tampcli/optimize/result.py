"""TrajectoryResult: what a stage of the optimizer returns (a status, never an exception)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from tampcli.optimize.values import Keyframes
from tampcli.solution_kkt import KktStages

# "bounded": the path stage stopped once its bound (motions solved so far plus the
# least cost through the keyframes of the rest) reached the caller's cutoff.
STATUSES = ("solved", "infeasible", "limit", "bounded")
STAGES = ("final", "reach", "keyframes", "path")


@dataclass(frozen=True)
class TrajectoryResult:
    """One stage's outcome for one skeleton.

    cost: the seed's smoothness term, sum of squared joint displacements between
        consecutive waypoints (path); sum over phases of |dq_keyframes|^2 / T
        (keyframes: the least path cost through those keyframes, by Cauchy-Schwarz;
        a local NLP optimum, hence `bound_kind = "heuristic"`); 0 for "final".
    violation: max constraint violation at the returned point (m or rad).
    worst_constraint: that violation in words, when not solved.
    kkt: the KKT certificate (optimize/kkt.py) of each stage solved on the way: a
        keyframes result carries its placements' (final) one too, a path result
        those of the keyframes it went through.
    proved: the infeasibility follows from the skeleton and the scene alone
        (lowering errors, an object larger than its region), not from an NLP failing.
    """

    status: str
    stage: str
    names: tuple[str, ...] = ()
    cost: float | None = None
    phase_costs: tuple[float, ...] = ()
    violation: float = 0.0
    worst_constraint: str | None = None
    iterations: int = 0
    nlp_solves: int = 0
    seconds: float = 0.0
    kkt: KktStages = KktStages()  # this stage's certificate and its warm start's
    bound_kind: str | None = None  # "proved" | "heuristic"
    proved: bool = False
    # Proved for every skeleton: no ground action of this schema may move this object
    # (with this mode role, when given; skeleton.ImpossibleAction): (action schema,
    # object, (role, value) or None).
    impossible: tuple | None = None
    # Path stage, failed: the skeleton's first N actions, through the action the motion
    # that failed leads to (what the failure depends on besides the keyframes).
    failed_actions: int | None = None
    trajectory: np.ndarray | None = field(default=None, repr=False)
    # (waypoints, k) the finger joints (World.finger_names) at each waypoint where the
    # hand is not open as loaded (optimize/hand.py); None: open unless closed on an object
    fingers: np.ndarray | None = field(default=None, repr=False)
    grasp_report: tuple = ()  # grasp_report.grasp_report: how each grasp holds its object
    phases: tuple = ()  # tampcli.solution.Phase
    object_poses: dict = field(default_factory=dict, repr=False)  # name -> [7-vector]
    # Warm starts for a later stage or a longer skeleton:
    keyframes: Keyframes = field(default_factory=Keyframes, repr=False)
    choices: dict = field(default_factory=dict, repr=False)  # step -> values.GripChoice
    # The keyframes were solved with the hand narrowed to these choices (hand.with_hand),
    # the open hand having failed; the path stage then keeps it so.
    narrowed: bool = False
    placements: dict = field(default_factory=dict, repr=False)  # step -> values.Placement
    grasps: dict = field(default_factory=dict, repr=False)  # object -> 4x4 in tool frame
    # Path stage, solved: each motion's interior waypoints (keyframe index -> (T_k - 1, n)),
    # the warm start of the same motions in a prefix of this skeleton (bnb/eliminate.py)
    motions: dict = field(default_factory=dict, repr=False)

    def __post_init__(self):
        if self.status not in STATUSES:
            raise ValueError(f"status must be one of {STATUSES}, got {self.status!r}")
        if self.stage not in STAGES:
            raise ValueError(f"stage must be one of {STAGES}, got {self.stage!r}")

    @property
    def solved(self) -> bool:
        return self.status == "solved"
