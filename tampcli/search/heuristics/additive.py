"""h_max, h_add and h_FF: one counter-based relaxed exploration each."""

from __future__ import annotations

from tampcli.search.heuristics.relaxed import INF, RelaxedTask
from tampcli.task.task import Task


class HMax:
    """Cost of the costliest goal fact under max-propagation (admissible)."""

    admissible = True

    def __init__(self, task: Task):
        self.relaxed = RelaxedTask(task)

    def __call__(self, state) -> float:
        dist, _ = self.relaxed.explore(state, additive=False)
        return dist[self.relaxed.goal]


class HAdd:
    """Sum of the goal facts' costs, preconditions summed (inadmissible)."""

    admissible = False

    def __init__(self, task: Task):
        self.relaxed = RelaxedTask(task)

    def __call__(self, state) -> float:
        dist, _ = self.relaxed.explore(state, additive=True)
        return dist[self.relaxed.goal]


class HFF:
    """Cost of a relaxed plan read off the h_add best supporters.

    An operator counts once however many of its relaxed copies (conditional
    effects) the relaxed plan uses. With `unit_cost` every operator costs 1
    (LAMA's first search: the number of steps left, whatever the costs);
    with `negations` the facts a condition needs false are facts to achieve
    (see relaxed.py).
    """

    admissible = False

    def __init__(self, task: Task, unit_cost: bool = False, negations: bool = False):
        self.relaxed = r = RelaxedTask(task, negations=negations)
        self.op_cost = [1.0 if unit_cost else op.cost for op in task.operators]
        self.costs = [1 if op >= 0 else 0 for op in r.op] if unit_cost else None
        self.integral = unit_cost

    def __call__(self, state) -> float:
        return self.relaxed_plan(state)[0]

    def relaxed_plan(self, state) -> tuple[float, set[int]]:
        """(cost, operator indices) of the relaxed plan; (inf, empty) at a dead end."""
        relaxed = self.relaxed
        dist, supporter = relaxed.explore(relaxed.seed(state), additive=True, costs=self.costs,
                                            integral=self.integral)
        if dist[relaxed.goal] == INF:
            return INF, set()
        pre, op_of = relaxed.pre, relaxed.op
        used_actions: set[int] = set()
        ops: set[int] = set()
        stack = [relaxed.goal]
        while stack:
            a = supporter[stack.pop()]
            if a is None or a < 0 or a in used_actions:
                continue
            used_actions.add(a)
            if op_of[a] >= 0:
                ops.add(op_of[a])
            stack.extend(pre[a])
        cost = self.op_cost
        return float(sum(cost[i] for i in ops)), ops


class Blind:
    """0 at a goal, else the cheapest operator cost (admissible, uninformed)."""

    admissible = True

    def __init__(self, task: Task):
        self.task = task
        self.step = min((op.cost for op in task.operators), default=0.0)

    def __call__(self, state) -> float:
        return 0.0 if self.task.is_goal(state) else self.step
