"""The delete relaxation of a Task as flat integer arrays, shared by the heuristics.

Relaxed actions: one per operator (its precondition, its unconditional adds),
one more per conditional effect (precondition + effect condition, the
effect's adds), one zero-cost action per axiom rule, and zero-cost actions
for the disjunctions of non-conjunctive conditions: an `or` node becomes an
auxiliary fact with one achiever per disjunct, so conditions stay linear in
size. Negative literals are dropped (they are assumed true), which keeps
every value below a relaxation of the real task: h_max and LM-cut stay
admissible. A single goal fact is reached by a zero-cost goal action.

With `negations`, a negated basic fact `not p` that some condition needs
becomes a fact of its own instead (as Fast Downward's translator does): true
in the states without p, added by the actions that delete p. Exploring then
starts from `seed(state)`. Still a relaxation (every real plan is a relaxed
one), and a better informed one where plans must undo things.
"""

from __future__ import annotations

import heapq

from tampcli.task.task import Condition, Task

INF = float("inf")


class RelaxedTask:
    def __init__(self, task: Task, init_fact: bool = False, negations: bool = False):
        self.task = task
        self.n_facts = len(task.facts)
        self.pre: list[tuple[int, ...]] = []
        self.add: list[tuple[int, ...]] = []
        self.cost: list[float] = []
        self.op: list[int] = []  # operator index, or -1 for axioms and auxiliary actions
        self._aux: dict = {}
        self.negated: dict[int, int] = {}  # basic fact -> the fact "it does not hold"
        if negations:
            for f in sorted(_negated_facts(task)):
                self.negated[f] = self._new_fact()
        negated = self.negated
        for i, op in enumerate(task.operators):
            base = self._relax(op.pre)
            adds = set(op.add) | {negated[f] for f in op.delete if f in negated}
            if adds:
                self._action(base, adds, op.cost, i)
            for eff in op.cond_effects:
                adds = set(eff.add) | {negated[f] for f in eff.delete if f in negated}
                if adds:
                    self._action(base | self._relax(eff.condition), adds, op.cost, i)
        for ax in task.axioms:
            self._action(set(ax.pos) | {negated[f] for f in ax.neg if f in negated},
                         (ax.head,), 0.0, -1)
        self.goal = self._new_fact()
        self._action(self._relax(task.goal), (self.goal,), 0.0, -1)
        # LM-cut wants every action to have a precondition: give the
        # precondition-free ones an artificial fact that every state holds.
        self.init_fact = None
        if init_fact:
            self.init_fact = self._new_fact()
            self.pre = [p if p else (self.init_fact,) for p in self.pre]
        self.n_actions = len(self.pre)
        self.pre_count = [len(p) for p in self.pre]
        self.pre_of: list[list[int]] = [[] for _ in range(self.n_facts)]
        for a, pre in enumerate(self.pre):
            for f in pre:
                self.pre_of[f].append(a)
        self.no_pre = [a for a in range(self.n_actions) if not self.pre[a]]
        self._aux = {}

    def _new_fact(self) -> int:
        self.n_facts += 1
        return self.n_facts - 1

    def _action(self, pre, add, cost: float, op: int) -> None:
        self.pre.append(tuple(sorted(set(pre))))
        self.add.append(tuple(sorted(set(add))))
        self.cost.append(float(cost))
        self.op.append(op)

    def seed(self, state) -> list[int]:
        """The relaxed facts true in `state`: its own, and the negations of the others."""
        if not self.negated:
            return list(state)
        return [*state, *(nf for f, nf in self.negated.items() if f not in state)]

    def _relax(self, cond: Condition) -> set[int]:
        facts = set(cond.pos)
        negated = self.negated
        if negated:
            facts.update(negated[f] for f in cond.neg if f in negated)
        for tree in cond.extra:
            facts |= self._relax_tree(tree)
        return facts

    def _relax_tree(self, tree) -> set[int]:
        if tree.__class__ is int:
            if tree >= 0:
                return {tree}
            return {self.negated[~tree]} if ~tree in self.negated else set()
        tag, parts = tree
        if tag == "and":
            out: set[int] = set()
            for p in parts:
                out |= self._relax_tree(p)
            return out
        fact = self._aux.get(tree)
        if fact is None:
            fact = self._new_fact()
            self._aux[tree] = fact
            for p in parts:
                self._action(self._relax_tree(p), (fact,), 0.0, -1)
        return {fact}

    # ------------------------------------------------------------ explorations

    def explore(self, state, additive: bool, costs=None, integral: bool = False):
        """h_add (additive) or h_max costs of every fact from `state`.

        Returns (dist, supporter): supporter[f] is the action that reached f
        cheapest, -1 for the state's facts and None for unreached ones.
        Stops as soon as the goal fact is reached: its one achiever, the goal
        action, fires only once every goal condition is settled, so its value
        is final then (with h_add it is far above the goal conditions' own
        costs, and exploring up to it would settle nearly every fact). `integral`: every cost is a
        whole number, so h_add can use a bucket queue in place of the heap.
        """
        costs = self.cost if costs is None else costs
        if additive and integral:
            return self._explore_buckets(state, costs)
        pre_of, adds, goal = self.pre_of, self.add, self.goal
        unsat = self.pre_count[:]
        acc = [0.0] * self.n_actions
        dist = [INF] * self.n_facts
        supporter: list = [None] * self.n_facts
        heap = []
        for f in state:
            dist[f] = 0.0
            supporter[f] = -1
            heap.append((0.0, f))
        if self.init_fact is not None:
            dist[self.init_fact] = 0.0
            supporter[self.init_fact] = -1
            heap.append((0.0, self.init_fact))
        heapq.heapify(heap)
        push, pop = heapq.heappush, heapq.heappop
        for a in self.no_pre:
            c = costs[a]
            for q in adds[a]:
                if c < dist[q]:
                    dist[q] = c
                    supporter[q] = a
                    push(heap, (c, q))
        while heap:
            c, f = pop(heap)
            if c > dist[f]:
                continue
            # facts reached at the popped cost itself (zero-cost axioms and
            # auxiliary actions) are settled at once, without the heap
            level = [f]
            while level:
                f = level.pop()
                if f == goal:
                    return dist, supporter
                for a in pre_of[f]:
                    left = unsat[a] - 1
                    unsat[a] = left
                    if additive:
                        acc[a] += c
                    if left == 0:
                        nc = (acc[a] if additive else c) + costs[a]
                        for q in adds[a]:
                            if nc < dist[q]:
                                dist[q] = nc
                                supporter[q] = a
                                if q == goal:
                                    return dist, supporter
                                if nc == c:
                                    level.append(q)
                                else:
                                    push(heap, (nc, q))
        return dist, supporter

    def _explore_buckets(self, state, costs):
        """h_add with whole-number costs: buckets of facts by cost, in place of the heap."""
        pre_of, adds, goal = self.pre_of, self.add, self.goal
        unsat = self.pre_count[:]
        acc = [0] * self.n_actions
        dist = [INF] * self.n_facts
        supporter: list = [None] * self.n_facts
        for f in state:
            dist[f] = 0
            supporter[f] = -1
        buckets: list[list[int]] = [list(state)]
        if self.init_fact is not None:
            dist[self.init_fact] = 0
            supporter[self.init_fact] = -1
            buckets[0].append(self.init_fact)
        for a in self.no_pre:
            c = int(costs[a])
            for q in adds[a]:
                if c < dist[q]:
                    dist[q] = c
                    supporter[q] = a
                    while len(buckets) <= c:
                        buckets.append([])
                    buckets[c].append(q)
        n_buckets = len(buckets)
        c = 0
        while c < n_buckets:
            bucket = buckets[c]
            # lowest fact first, as the heap pops (c, f): the supporters, hence
            # the relaxed plans and preferred operators, are the heap's own
            if len(bucket) > 1:
                bucket.sort(reverse=True)
            while bucket:
                f = bucket.pop()
                if dist[f] != c:
                    continue
                if f == goal:
                    return dist, supporter
                for a in pre_of[f]:
                    left = unsat[a] - 1
                    unsat[a] = left
                    acc[a] += c
                    if left == 0:
                        nc = acc[a] + costs[a]
                        for q in adds[a]:
                            if nc < dist[q]:
                                dist[q] = nc
                                supporter[q] = a
                                if q == goal:
                                    return dist, supporter
                                if nc >= n_buckets:
                                    buckets.extend([] for _ in range(nc + 1 - n_buckets))
                                    n_buckets = nc + 1
                                buckets[nc].append(q)
            c += 1
        return dist, supporter


def _negated_facts(task: Task) -> set[int]:
    """The basic facts some condition needs false (derived ones cannot be deleted)."""
    found: set[int] = set()

    def tree(t) -> None:
        if t.__class__ is int:
            if t < 0:
                found.add(~t)
            return
        for part in t[1]:
            tree(part)

    def condition(c: Condition) -> None:
        found.update(c.neg)
        for t in c.extra:
            tree(t)

    for op in task.operators:
        condition(op.pre)
        for eff in op.cond_effects:
            condition(eff.condition)
    condition(task.goal)
    for ax in task.axioms:
        found.update(ax.neg)
    return found - task.derived
