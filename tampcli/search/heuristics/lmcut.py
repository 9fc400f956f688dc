"""LM-cut (Helmert & Domshlak 2009): admissible, from disjunctive action landmarks.

Each round computes h_max under the remaining action costs, with each
action's precondition choice (its costliest precondition), then cuts the
justification graph between the facts reachable from the state without
passing the goal zone (facts that reach the goal through zero-cost actions)
and the goal zone. The cut's cheapest cost is added to h and subtracted
from every action of the cut, until the goal's h_max is 0.
"""

from __future__ import annotations

import heapq

from tampcli.errors import UnsupportedFeatureError
from tampcli.search.heuristics.relaxed import INF, RelaxedTask
from tampcli.task.task import Task


class LMCut:
    admissible = True

    def __init__(self, task: Task):
        for op in task.operators:
            if op.cond_effects:
                raise UnsupportedFeatureError(
                    f"heuristic lmcut does not support conditional effects (operator {op.name}); "
                    "use --heuristic hmax for optimal planning, or hff",
                    key="--heuristic")
        self.relaxed = r = RelaxedTask(task, init_fact=True)
        self.achievers: list[list[int]] = [[] for _ in range(r.n_facts)]
        for a, adds in enumerate(r.add):
            for q in adds:
                self.achievers[q].append(a)

    def _hmax(self, state, costs):
        """h_max of every fact; each action's choice (costliest precondition) and,
        per fact, the actions that chose it (may hold stale entries: check `choice`)."""
        r = self.relaxed
        pre_of, adds = r.pre_of, r.add
        unsat = r.pre_count[:]
        dist = [INF] * r.n_facts
        choice: list = [None] * r.n_actions
        chosen_by: list[list[int]] = [[] for _ in range(r.n_facts)]
        heap = [(0.0, f) for f in state]
        heap.append((0.0, r.init_fact))
        for _, f in heap:
            dist[f] = 0.0
        heapq.heapify(heap)
        push, pop = heapq.heappush, heapq.heappop
        while heap:
            c, f = pop(heap)
            if c > dist[f]:
                continue
            chosen = chosen_by[f]
            for a in pre_of[f]:
                left = unsat[a] - 1
                unsat[a] = left
                if left == 0:
                    # facts pop in non-decreasing order: f is the costliest precondition
                    choice[a] = f
                    chosen.append(a)
                    nc = c + costs[a]
                    for q in adds[a]:
                        if nc < dist[q]:
                            dist[q] = nc
                            push(heap, (nc, q))
        return dist, choice, chosen_by

    def _lower(self, cut, costs, dist, choice, chosen_by) -> None:
        """Propagate the h_max decreases caused by cheaper cut actions.

        Costs only decrease, so h_max values only decrease, and an action's
        value changes only when its chosen (costliest) precondition does.
        """
        r = self.relaxed
        pre, adds = r.pre, r.add
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

    def __call__(self, state) -> float:
        r = self.relaxed
        goal, n_facts = r.goal, r.n_facts
        adds, achievers = r.add, self.achievers
        costs = r.cost[:]
        dist, choice, chosen_by = self._hmax(state, costs)
        if dist[goal] == INF:
            return INF
        roots = [*state, r.init_fact]
        h = 0.0
        while dist[goal] > 0.0:
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
            # the justification graph has an edge choice(a) -> q for every
            # add q of a: the cut is every edge from the facts reachable
            # without entering the goal zone into the goal zone
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
                    into_zone = False
                    for q in adds[a]:
                        if zone[q]:
                            into_zone = True
                        elif not reached[q]:
                            reached[q] = 1
                            stack.append(q)
                    if into_zone:
                        cut.add(a)
            m = min(costs[a] for a in cut)
            h += m
            for a in cut:
                costs[a] -= m
            self._lower(cut, costs, dist, choice, chosen_by)
        return h
