"""Mode kinds: what each `mode` of modes.toml means, one module per kind.

Every stage (lowering, the final and keyframe NLPs, the initial guess, the
trajectory's phases, verify, the video's replay) asks an action's kind
instead of naming it; a new kind is a new module here and one line below.
"""

from __future__ import annotations

from tampcli.optimize.kinds.base import ModeKind
from tampcli.optimize.kinds.grasp import Grasp
from tampcli.optimize.kinds.move import Move
from tampcli.optimize.kinds.none import Symbolic
from tampcli.optimize.kinds.place import Place
from tampcli.optimize.kinds.push import Push

KINDS: dict[str, ModeKind] = {kind.name: kind for kind in (
    Grasp(),
    Place(),
    Push(),
    Move(),
    Symbolic(),
)}
SYMBOLIC = KINDS[Symbolic.name]  # an action without a mode
MOTION = KINDS[Move.name]  # a motion that is no action of the plan (a retreat after the last)

__all__ = ["KINDS", "MOTION", "SYMBOLIC", "ModeKind"]
