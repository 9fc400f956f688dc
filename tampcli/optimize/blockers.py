"""Which body blocked which action: a failed NLP's worst row, read back as a Blocker.

The rows of the NLPs are labelled with the action they serve (the final
and keyframe NLPs: `(place a goal): overlaps b`; the path NLP: `motion 2
before (pick a floor): collision panda_hand vs b`). When the worst row left
violated names a movable body that the action did not handle itself, that
body stood in the way: branch and bound passes the finding to the skeleton
source (search/learned.py), which orders next the skeletons that move it
first. A push whose own rule is the worst row (`(push a x y): motion not into
the pushed face`: from where `a` stands no face's friction cone leads into the
target) teaches the same of `a` itself: skeletons that move it elsewhere before
that push come next. A wrong guess costs order, never a solution: the source falls back to
the plain enumeration.
"""

from __future__ import annotations

import re

from tampcli.search.learned import Blocker

_ACTION = re.compile(r"(\([^()]*\))")
_OVERLAP = re.compile(r": overlaps (?P<b>[^\s:]+)")
_COLLISION = re.compile(r": collision (?P<a>[^\s:]+) vs (?P<b>[^\s:]+)")
_PUSH_RULE = re.compile(r": motion not into the pushed face")


def blocker_of(worst: str | None, movable: frozenset[str]) -> Blocker | None:
    """The Blocker a worst-row message names, or None (not an obstruction by a movable body)."""
    if not worst:
        return None
    action = _ACTION.search(worst)
    if action is None:
        return None
    name = action.group(1)
    args = set(name.strip("()").split()[1:])
    if _PUSH_RULE.search(worst):
        # The push cannot go from where its object stands (no face's cone leads into the
        # target): skeletons that move the object elsewhere first come next.
        pushed = sorted(args & movable)
        return Blocker(pushed[0], name) if len(pushed) == 1 else None
    found = _OVERLAP.search(worst) or _COLLISION.search(worst)
    if found is None:
        return None
    for body in (found.group("b"), found.groupdict().get("a")):
        if body in movable and body not in args:
            return Blocker(body, name)
    return None


def fixed_obstacle_of(worst: str | None, movable: frozenset[str]) -> str | None:
    """The action a worst-row message names when a collision with a body that never
    moves (a wall, a post: not in `movable`) is what failed, else None. For a push
    (whose motion keeps to one face's friction cone) that reads as "this push runs
    into the scene's fixed geometry wherever it stands in a skeleton": a guess, which
    bnb/lessons.py turns into an ordering (LearningSource.suspect), never a proof."""
    return action_of(worst) if fixed_body_of(worst, movable) is not None else None


def fixed_body_of(worst: str | None, movable: frozenset[str]) -> str | None:
    """The body that never moves a collision row of `worst` names, else None."""
    found = _COLLISION.search(worst or "")
    return found.group("b") if found is not None and found.group("b") not in movable \
        else None


def action_of(worst: str | None) -> str | None:
    """The first ground action a worst-row message names, else None."""
    found = _ACTION.search(worst or "")
    return found.group(1) if found is not None else None
