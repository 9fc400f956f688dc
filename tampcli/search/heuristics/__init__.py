"""Heuristics: `HEURISTICS[name](task) -> callable(state) -> float` (inf = dead end).

All work on the delete relaxation built in relaxed.py, so conditional
effects, disjunctive conditions and axioms are supported by blind, h_max,
h_add and h_FF; LM-cut refuses conditional effects (an UnsupportedFeatureError
that names an alternative). `admissible` says which values may be used by an
optimal search. The landmark count (lmcount) is path-dependent: a search
that knows each state's first parent tells it with `progress(parent, state)`.
"""

from __future__ import annotations

from tampcli.search.heuristics.additive import HFF, Blind, HAdd, HMax
from tampcli.search.heuristics.landmarks import LandmarkCount
from tampcli.search.heuristics.lmcut import LMCut

HEURISTICS = {
    "hff": HFF,
    "hadd": HAdd,
    "hmax": HMax,
    "lmcut": LMCut,
    "lmcount": LandmarkCount,
    "blind": Blind,
}

__all__ = ["HEURISTICS", "HFF", "Blind", "HAdd", "HMax", "LMCut", "LandmarkCount"]
