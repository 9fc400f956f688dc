"""What a failed stage teaches the skeleton source (search/learned.py).

Two lessons, both read off the stage's result:

- a body in the way (its worst row names a movable body: optimize/blockers.py)
  becomes a learned precondition: the skeletons that move it first come next;
- an action proved impossible in any skeleton (`result.impossible`: no grasp of
  the object fits, its footprint fits the region in no orientation) takes
  every ground action of that schema on that object (into that region) out
  of the task: the enumeration runs out once no plan without one is left.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from tampcli.optimize.blockers import blocker_of


def teacher(source, task, modes, movable: frozenset[str]) -> Callable[[Any], None]:
    """`learn(result)` for branch and bound: `source` a LearningSource over `task`."""

    def matches(op, action: str, obj: str, role) -> bool:
        if op.action != action:
            return False
        bound = modes.get_mode(action).bind(op.args)
        return bound["object"] == obj and (role is None or bound[role[0]] == role[1])

    def learn(result) -> None:
        blocker = blocker_of(getattr(result, "worst_constraint", None), movable)
        if blocker is not None:
            source.learn(blocker)
        impossible = getattr(result, "impossible", None)
        if impossible is not None:
            source.forbid_operators(frozenset(
                op.name for op in task.operators if matches(op, *impossible)))

    return learn
