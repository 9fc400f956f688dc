"""none: a symbolic action; nothing moves, and it takes no time in the trajectory."""

from __future__ import annotations

from tampcli.optimize.kinds.base import ModeKind
from tampcli.optimize.skeleton import Step


class Symbolic(ModeKind):
    name = "none"
    geometric = False

    def lower(self, lo, index, op, mode):
        return Step(index, op.name, self, held_before=lo.held, held_after=lo.held)

    def grip(self, problem, step, choice):
        raise ValueError(f"{step.name}: a symbolic action holds nothing")

    def final_rows(self, walk, step):
        pass

    def guess(self, walk, step):
        pass

    def reseed(self, walk, step, k):
        pass

    def keyframe_rows(self, walk, step):
        pass

    def switch(self, walk, step):
        pass

    def phases(self, walk, step):
        walk.instant(step)

    def check(self, walk, step):
        return []
