"""The task a skeleton source enumerates, with what geometry found compiled in.

A `Blocker` (a body in the way of a ground action) becomes a fact `(moved b)`
added by every operator that moves b and required by the action it blocked
(`compile_task`): learned ones order skeletons (search/learned.py's
LearningSource), proved ones filter them (its `require_moved`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass, field

from tampcli.task.task import Operator, Task

MOVED = "(tampcli-moved {})"  # the fact a learned precondition asks for
PROVED = "(tampcli-moved-first {})"  # the fact a proved precondition asks for (require_moved)


@dataclass(frozen=True)
class Blocker:
    """`body`, where it stood, blocked the ground action `action` (its name); `why`,
    for a proof, what proves it (not part of its identity)."""

    body: str
    action: str
    why: str = field(default="", compare=False)

    def words(self) -> str:
        return f"{self.body} moved before {self.action}" + (f" ({self.why})" if self.why
                                                              else "")


def compile_task(task: Task, blockers: frozenset[Blocker],
                 moves: Callable[[Operator], frozenset[str]], fact_name: str = MOVED) -> Task:
    """The task with a `(moved b)` fact per blocking body (`fact_name`): added by
    every operator that moves b, a precondition of each operator b blocked."""
    bodies = sorted({b.body for b in blockers})
    fact = {body: len(task.facts) + i for i, body in enumerate(bodies)}
    needs: dict[str, set[int]] = {}
    for b in blockers:
        needs.setdefault(b.action, set()).add(fact[b.body])
    operators = []
    for op in task.operators:
        adds = {fact[body] for body in moves(op) if body in fact}
        pre = needs.get(op.name)
        if adds or pre:
            op = dataclasses.replace(
                op, add=op.add | adds,
                pre=dataclasses.replace(op.pre, pos=op.pre.pos | frozenset(pre or ())))
        operators.append(op)
    return dataclasses.replace(task, facts=task.facts + tuple(fact_name.format(b) for b in bodies),
                               operators=tuple(operators))


def is_subsequence(short: tuple[str, ...], long: tuple[str, ...]) -> bool:
    rest = iter(long)
    return all(any(name == other for other in rest) for name in short)


def passes_twice(task: Task, plan, times: int) -> bool:
    """Whether `plan` passes a state of `task` (as given: no learned or proved facts)
    more than `times` times (an enumeration that allows 1 + revisits)."""
    state = task.init
    seen = {state: 1}
    for op in plan.operators:
        state = task.apply(state, op)
        seen[state] = seen.get(state, 0) + 1
        if seen[state] > times:
            return True
    return False
