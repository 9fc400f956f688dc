"""LM-cut that also returns its landmarks, for cheap admissible bounds on successors.

LM-cut's cuts are disjunctive action landmarks L_1..L_n of the state s with
costs m_1..m_n, such that no operator is charged more than its cost in all
the landmarks containing it. If an operator o is not in L_i, every plan from
s' = s[o] is, after o, a plan from s, so it uses an operator of L_i: L_i is
still a landmark of s'. Hence sum(m_i for L_i not containing o) is an
admissible value for s' (the path-dependent LM-cut bound), known without
running LM-cut on s'. The bounded exploration queues successors with it and
runs LM-cut only on the states it cannot prune; and it stops LM-cut early
once the value passes what matters (`budget`): every partial sum of the
landmark costs is admissible too.

When LM-cut does run on s', it starts from those inherited landmarks (the
idea of incremental LM-cut, Pommerening & Helmert 2013): their costs are
counted and taken off their actions first, then cuts are added under the
remaining costs. The landmarks together still charge no action more than
its cost, so the sum stays admissible; it depends on the parent s' was
reached from, and needs far fewer cuts than LM-cut from scratch (on
elevators p01 it is mostly higher, too: fewer states get expanded).

Only for tasks without conditional effects (as LM-cut itself): then each
operator has at most one relaxed action, so a charge per relaxed action is a
charge per operator. Kept apart from `heuristics.lmcut` (same algorithm, own
code) because the search needs the landmarks and the budget, not only h.
"""

from __future__ import annotations

import heapq

from tampcli.errors import UnsupportedFeatureError
from tampcli.search.heuristics.relaxed import INF, RelaxedTask
from tampcli.task.task import Task


class LandmarkCut:
    admissible = True

    def __init__(self, task: Task):
        for op in task.operators:
            if op.cond_effects:
                raise UnsupportedFeatureError(
                    f"LM-cut does not support conditional effects (operator {op.name})")
        self.relaxed = r = RelaxedTask(task, init_fact=True)
        self.achievers: list[list[int]] = [[] for _ in range(r.n_facts)]
        for a, adds in enumerate(r.add):
            for q in adds:
                self.achievers[q].append(a)
        # operator -> its relaxed action (one at most: no conditional effects)
        self.action_of = {o: a for a, o in enumerate(r.op) if o >= 0}

    def __call__(self, state) -> float:
        return self.landmarks(state)[0]

    def landmarks(self, state, budget: float = INF, resume=None, inherited=()):
        """(h, [(cost, operator indices of the landmark), ...], rest) for `state`.

        Stops as soon as h exceeds `budget`; `rest` is then a token that
        `resume` takes to go on from there later with a larger budget, and
        None when h is complete. `inherited`: landmarks of `state` already
        known (a parent's that the operator to here is not in): counted
        first, their costs taken off the actions' before cutting further.
        """
        r = self.relaxed
        goal, n_facts, adds, achievers, op_of = r.goal, r.n_facts, r.add, self.achievers, r.op
        if resume is None:
            costs = r.cost[:]
            h, found = 0.0, list(inherited)
            action_of = self.action_of
            for m, ops in found:
                h += m
                for o in ops:
                    a = action_of[o]
                    left = costs[a] - m
                    costs[a] = left if left > 0.0 else 0.0
            dist, choice, chosen_by = self._hmax(state, costs)
            if dist[goal] == INF:
                return INF, [], None
            if h + dist[goal] > budget:  # h_max alone is enough
                return h + dist[goal], found, (costs, dist, choice, chosen_by, h, found)
        else:
            costs, dist, choice, chosen_by, h, found = resume
            if h + dist[goal] > budget:
                return h + dist[goal], found, resume
        roots = [*state, r.init_fact]
        while dist[goal] > 0.0:
            # the goal zone: facts that reach the goal through zero-cost actions
            zone = bytearray(n_facts)
            zone[goal] = 1
            stack = [goal]
            while stack:
                f = stack.pop()
                for a in achievers[f]:
                    p = choice[a]
                    if p is not None and costs[a] == 0.0 and not zone[p]:
                        zone[p] = 1
                        stack.append(p)
            # the cut: actions whose chosen precondition is reached from the
            # state without entering the zone, and that add a fact of the zone
            reached = bytearray(n_facts)
            for f in roots:
                reached[f] = 1
            stack = roots[:]
            cut = set()
            while stack:
                f = stack.pop()
                for a in chosen_by[f]:
                    if choice[a] != f:
                        continue
                    into = False
                    for q in adds[a]:
                        if zone[q]:
                            into = True
                        elif not reached[q]:
                            reached[q] = 1
                            stack.append(q)
                    if into:
                        cut.add(a)
            m = min(costs[a] for a in cut)
            h += m
            found.append((m, frozenset(op_of[a] for a in cut)))
            for a in cut:
                costs[a] -= m
            self._lower(cut, costs, dist, choice, chosen_by)
            if h + dist[goal] > budget and dist[goal] > 0.0:
                # h + the remaining h_max is admissible too (a cost partition)
                return h + dist[goal], found, (costs, dist, choice, chosen_by, h, found)
        return h, found, None

    def _hmax(self, state, costs):
        """h_max per fact; per action its costliest precondition; per fact the
        actions that chose it (stale entries possible: check `choice`)."""
        r = self.relaxed
        pre_of, adds = r.pre_of, r.add
        unsat = r.pre_count[:]
        dist = [INF] * r.n_facts
        choice: list = [None] * r.n_actions
        # a list only for the facts that get settled (the others are never read)
        chosen_by: list = [()] * r.n_facts
        level = [*state, r.init_fact]  # the facts reached at cost c, not processed yet
        for f in level:
            dist[f] = 0.0
        heap: list = []
        push, pop = heapq.heappush, heapq.heappop
        c = 0.0
        while True:
            while level:
                f = level.pop()
                chosen = chosen_by[f] = []
                for a in pre_of[f]:
                    left = unsat[a] - 1
                    unsat[a] = left
                    if left == 0:  # facts settle in cost order: f is the costliest precondition
                        choice[a] = f
                        chosen.append(a)
                        nc = c + costs[a]
                        for q in adds[a]:
                            if nc < dist[q]:
                                dist[q] = nc
                                # zero-cost actions (many, once landmarks are taken
                                # off) settle their facts at once, without the heap
                                if nc == c:
                                    level.append(q)
                                else:
                                    push(heap, (nc, q))
            while heap:
                c, f = pop(heap)
                if c == dist[f]:
                    level.append(f)
                    break
            if not level:
                break
        return dist, choice, chosen_by

    def _lower(self, cut, costs, dist, choice, chosen_by) -> None:
        """Propagate the h_max decreases after the cut actions got cheaper.

        Costs only decrease, so values only decrease, and an action's value
        changes only through its chosen precondition.
        """
        pre, adds = self.relaxed.pre, self.relaxed.add
        heap = []
        for a in cut:
            nc = dist[choice[a]] + costs[a]
            for q in adds[a]:
                if nc < dist[q]:
                    dist[q] = nc
                    heap.append((nc, q))
        heapq.heapify(heap)
        push, pop = heapq.heappush, heapq.heappop
        while heap:
            c, f = pop(heap)
            if c > dist[f]:
                continue
            for a in chosen_by[f]:
                if choice[a] != f:
                    continue
                best, arg = -1.0, f
                for p in pre[a]:
                    if dist[p] > best:
                        best, arg = dist[p], p
                if arg != f:
                    choice[a] = arg
                    chosen_by[arg].append(a)
                nc = best + costs[a]
                for q in adds[a]:
                    if nc < dist[q]:
                        dist[q] = nc
                        push(heap, (nc, q))
