"""A skeleton pruned by the reach bound of a short prefix of it.

The reach stage's NLP (keyframes with collisions dropped) of a prefix is a
relaxation of the whole skeleton's: the prefix's rows are a subset, and the
motions the rest adds cost >= 0. So where the incumbent leaves a skeleton a
small margin (its symbolic cost is already most of the incumbent's objective),
the reach of its first few actions can prune it at a fraction of the whole
reach's cost (arm-hanoi p01: skeletons of 22 actions, 0.0155 of trajectory
cost to spare, each pruned after a reach over 22 keyframes, 0.8 s).
Heuristic as the reach bound itself is (both are local optima).

Which prefix: the shortest, ending at a geometric action, that the incumbent's
trajectory cost per geometric action says should cost `SAFETY` times the
margin; tried only when it is at most `SHARE` of the skeleton's geometric
actions (otherwise the whole reach, which comes next anyway, is little more).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

SAFETY = 2.0  # the prefix is expected to cost this many times the margin
SHARE = 0.5  # of the skeleton's geometric actions, at most


def per_action(cost: float | None, plan: Sequence[Any],
               is_geometric: Callable[[Any], bool]) -> float | None:
    """The incumbent's trajectory cost per geometric action (None without one)."""
    n = sum(1 for op in plan if is_geometric(op))
    if cost is None or n == 0 or not math.isfinite(cost) or cost <= 0.0:
        return None
    return cost / n


def prefix_length(ops: Sequence[Any], is_geometric: Callable[[Any], bool], margin: float,
                  each: float | None) -> int | None:
    """How many of `ops` make the prefix worth a reach NLP of its own, or None.

    `margin`: the trajectory cost at which the skeleton cannot beat the
    incumbent; `each`: the incumbent's cost per geometric action (per_action).
    """
    if each is None or margin <= 0.0:
        return None
    ends = [i for i in range(1, len(ops) + 1) if is_geometric(ops[i - 1])]
    need = max(2, math.ceil(SAFETY * margin / each))  # a pick and its place at least
    if need > SHARE * len(ends) or need > len(ends):
        return None
    return ends[need - 1]


def prunes(result, symbolic_part: float, incumbent: float) -> bool:
    """Whether a prefix's reach result bounds the skeleton at or above the incumbent."""
    return (result is not None and result.status == "solved" and result.cost is not None
            and result.cost + symbolic_part >= incumbent)


def pruning_reach(ops: Sequence[Any], is_geometric: Callable[[Any], bool], incumbent: float,
                  symbolic_part: float, each: float | None, solve: Callable[[int], Any]):
    """The reach result of the prefix `prefix_length` picks, where it prunes the
    skeleton; None otherwise (no incumbent, no prefix worth it, or not pruned).
    `solve(i)`: the reach stage of the first i actions."""
    if not math.isfinite(incumbent):
        return None
    i = prefix_length(ops, is_geometric, incumbent - symbolic_part, each)
    if i is None:
        return None
    result = solve(i)
    return result if prunes(result, symbolic_part, incumbent) else None
