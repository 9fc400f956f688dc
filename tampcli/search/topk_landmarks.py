"""LM-cut that also returns its landmarks, for cheap admissible bounds on successors.

LM-cut's cuts are disjunctive action landmarks L_1..L_n of the state s with
costs m_1..m_n, such that no operator is charged more than its cost in all
the landmarks containing it. If an operator o is not in L_i, every plan from
s' = s[o] is, after o, a plan from s, so it uses an operator of L_i: L_i is
still a landmark of s'. Hence sum(m_i for L_i not containing o) is an
admissible value for s' (Pommerening & Helmert's path-dependent LM-cut
bound), known without running LM-cut on s'. The bounded exploration queues
successors with it and runs LM-cut only on the states it cannot prune.

Only for tasks without conditional effects (as LM-cut itself): then each
operator has at most one relaxed action, so charges per relaxed action are
charges per operator.
"""

from __future__ import annotations

from tampcli.search.heuristics.lmcut import LMCut
from tampcli.search.heuristics.relaxed import INF


class LandmarkCut(LMCut):
    def __call__(self, state) -> float:
        return self.landmarks(state)[0]

    def landmarks(self, state) -> tuple[float, list[tuple[float, frozenset[int]]]]:
        """(h, [(cost, operator indices of the landmark), ...]) for `state`."""
        r = self.relaxed
        goal, n_facts = r.goal, r.n_facts
        pre_of, adds, achievers, op_of = r.pre_of, r.add, self.achievers, r.op
        costs = r.cost[:]
        dist, choice = self._hmax(state, costs)
        if dist[goal] == INF:
            return INF, []
        roots = [*state, r.init_fact]
        h = 0.0
        found: list[tuple[float, frozenset[int]]] = []
        while dist[goal] > 0.0:
            # the goal zone: facts reaching the goal through zero-cost actions
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
            cut = []
            while stack:
                f = stack.pop()
                for a in pre_of[f]:
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
                        cut.append(a)
            m = min(costs[a] for a in cut)
            h += m
            found.append((m, frozenset(op_of[a] for a in cut)))
            for a in cut:
                costs[a] -= m
            self._lower(cut, costs, dist, choice)
        return h, found
