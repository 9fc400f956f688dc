"""The part of the state space that can hold plans of cost <= B, grown as B grows.

`BoundedGraph.explore(B)` expands, with an admissible h, every state reached
with some g such that g + h(state) <= B, re-expanding a state whenever a
cheaper g to it is found; with a limit it stops earlier, in the same order
(lowest g + h first, then the deepest). Claim: after a complete
`explore(B)` every state on every plan of cost <= B is expanded. Induction
along such a plan s0 .. sn: s0 is pushed with g = 0, and 0 + h(s0) <=
h*(s0) <= B. If s_i was expanded with its final g(s_i) <= g_plan(s_i),
s_{i+1} was offered g <= g_plan(s_{i+1}), and g + h(s_{i+1}) <=
g_plan(s_{i+1}) + h*(s_{i+1}) <= B, so it was expanded too (with a g that
can only have dropped since). `distances` turns the expanded part into
lower bounds on the cost to a goal (see topk.py for how they are used).

Heuristic values are computed lazily: a child is queued with a bound known
from its parent, h(parent) - c(parent, child) (admissible: h(parent) <=
h*(parent) <= c + h*(child)), or better the parent's landmarks that the
operator does not touch (topk_landmarks.py), and the heuristic runs only
when the child comes out of the queue at a key <= B.
"""

from __future__ import annotations

import heapq
from collections.abc import Callable

from tampcli.task.task import Task

INF = float("inf")


class TimeUp(Exception):
    """The time limit passed while exploring or enumerating."""


class BoundedGraph:
    def __init__(self, task: Task, heuristic: Callable[[frozenset], float],
                 check_time: Callable[[], None]):
        self.task, self.heuristic, self.check_time = task, heuristic, check_time
        self.op_index = {id(op): i for i, op in enumerate(task.operators)}
        self.costs = [op.cost for op in task.operators]
        self.states: list[frozenset] = []
        self.ids: dict[frozenset, int] = {}
        self.g: list[float] = []
        self.h: list[float | None] = []
        self.hlow: list[float] = []  # best admissible bound known before evaluating h
        self._landmarks: dict[int, tuple] = {}  # of evaluated states not yet expanded
        self._partial: dict[int, tuple] = {}  # LM-cut stopped at a budget, to resume
        self._with_landmarks = getattr(heuristic, "landmarks", None)
        # per state, (op index, successor id) of every applicable op once expanded
        self.succ: list[tuple[tuple[int, int], ...] | None] = []
        self.goal: list[bool] = []
        # (key, -g, seq, id): among equal keys the deepest first, so that a
        # layer explored only in part already holds whole paths to goals
        self.open: list[tuple[float, float, int, int]] = []
        self.seq = 0
        self.expansions = 0
        self.evaluations = 0
        self._id(task.init, 0.0, 0.0)

    @property
    def complete(self) -> bool:
        """Nothing left to expand: the expanded part is all that is reachable."""
        return not self.open

    def _id(self, state: frozenset, g: float, h_bound: float) -> int:
        """The id of `state`, reached with cost g, queued if new or reached more cheaply."""
        sid = self.ids.get(state)
        if sid is None:
            sid = len(self.states)
            self.ids[state] = sid
            self.states.append(state)
            self.g.append(g)
            self.h.append(None)
            self.hlow.append(max(h_bound, 0.0))
            self.succ.append(None)
            self.goal.append(False)
        else:
            if h_bound > self.hlow[sid]:
                self.hlow[sid] = h_bound
            if g >= self.g[sid]:
                return sid
            self.g[sid] = g
        known = self.h[sid]
        self._requeue(g + (known if known is not None else self.hlow[sid]), g, sid)
        return sid

    def next_key(self) -> float:
        """The smallest g + h bound among states still to expand (inf if none)."""
        self._drop_stale()
        return self.open[0][0] if self.open else INF

    def _drop_stale(self) -> None:
        while self.open and -self.open[0][1] > self.g[self.open[0][3]]:
            heapq.heappop(self.open)

    def explore(self, bound: float, limit: int | None = None) -> bool:
        """Expand every state whose g + h is <= bound (see the module docstring).

        With `limit`, stop after that many expansions; True when done.
        """
        successors, index, costs = self.task.successors, self.op_index, self.costs
        stop = None if limit is None else self.expansions + limit
        while True:
            self._drop_stale()
            if not self.open or self.open[0][0] > bound:
                return True
            if stop is not None and self.expansions >= stop:
                return False
            key, g, _, sid = heapq.heappop(self.open)
            g = -g
            h = self.h[sid]
            if h is None:
                if g + self.hlow[sid] > key:  # a better bound arrived since it was queued
                    self._requeue(g + self.hlow[sid], g, sid)
                    continue
                h = self._evaluate(sid, bound - g)
                if g + h > key:  # the lazy bound was loose: queue with a better one
                    if h < INF:
                        self._requeue(g + h, g, sid)
                    continue
                h = self.h[sid]
            succ = self.succ[sid]
            if succ is None:
                self.expansions += 1
                if self.expansions % 256 == 0:
                    self.check_time()
                state = self.states[sid]
                self.goal[sid] = self.task.is_goal(state)
                child_bound = self._child_bounds(sid, h)
                succ = self.succ[sid] = tuple(
                    (index[id(op)], self._id(nxt, g + op.cost, child_bound(index[id(op)])))
                    for op, nxt in successors(state))
            else:
                for op, nid in succ:
                    self._id(self.states[nid], g + costs[op], h - costs[op])

    def expand_now(self, sid: int) -> None:
        """Expand one state out of the exploration's order (evaluated in full first)."""
        if self.succ[sid] is not None:
            return
        h = self.h[sid]
        if h is None:
            h = self._evaluate(sid, INF)
        if h == INF:
            return
        self.expansions += 1
        index, state, g = self.op_index, self.states[sid], self.g[sid]
        self.goal[sid] = self.task.is_goal(state)
        child_bound = self._child_bounds(sid, h)
        self.succ[sid] = tuple(
            (index[id(op)], self._id(nxt, g + op.cost, child_bound(index[id(op)])))
            for op, nxt in self.task.successors(state))

    def _requeue(self, key: float, g: float, sid: int) -> None:
        self.seq += 1
        heapq.heappush(self.open, (key, -g, self.seq, sid))

    def _evaluate(self, sid: int, budget: float) -> float:
        """h of the state, or only a bound above `budget` when that is cheaper.

        Sets self.h[sid] when the value is exact, else raises self.hlow[sid].
        """
        self.evaluations += 1
        if self.evaluations % 64 == 0:
            self.check_time()
        state = self.states[sid]
        if self._with_landmarks is None:
            value, complete = self.heuristic(state), True
        else:
            value, found, rest = self._with_landmarks(state, budget, self._partial.pop(sid, None))
            complete = rest is None
            if not complete:
                self._partial[sid] = rest
            elif found:
                self._landmarks[sid] = (value, found)
        value = max(value, self.hlow[sid])  # both admissible: keep the larger
        if complete:
            self.h[sid] = value
        else:
            self.hlow[sid] = value
        return value

    def _child_bounds(self, sid: int, h: float):
        """op index -> admissible bound on the h of the successor by that op."""
        costs = self.costs
        marked = self._landmarks.pop(sid, None)
        if marked is None:
            return lambda op: h - costs[op]
        total, found = marked
        charged: dict[int, float] = {}
        for m, ops in found:
            for op in ops:
                charged[op] = charged.get(op, 0.0) + m
        return lambda op: max(h - costs[op], total - charged.get(op, 0.0))

    def lower_bound(self, sid: int) -> float:
        """The admissible h known for a state (its h, else its lazy bound)."""
        known = self.h[sid]
        return known if known is not None else self.hlow[sid]

    def distances(self) -> tuple[list[float], bytearray]:
        """A lower bound on the cost to a goal of every plan from each known state.

        The cheapest cost to a goal when every continuation stays in the
        expanded part; a continuation that leaves it at a state not expanded
        yet counts that state's admissible h (or bound) from there. The
        second list flags the states whose value comes from such a state
        (at equal values, a way to a goal wins).
        """
        n = len(self.states)
        preds: list[list[tuple[float, int]]] = [[] for _ in range(n)]
        costs = self.costs
        dist = [INF] * n
        open_end = bytearray(n)
        heap = []
        for sid, succ in enumerate(self.succ):
            if succ is None:
                bound = self.lower_bound(sid)
                if bound < INF:
                    dist[sid] = bound
                    open_end[sid] = 1
                    heap.append((bound, 1, sid))
                continue
            if self.goal[sid]:
                dist[sid] = 0.0
                heap.append((0.0, 0, sid))
            for op, nid in succ:
                preds[nid].append((costs[op], sid))
        heapq.heapify(heap)
        while heap:
            d, flag, sid = heapq.heappop(heap)
            if d > dist[sid] or flag > open_end[sid]:
                continue
            for c, pid in preds[sid]:
                nd = d + c
                if nd < dist[pid] or (nd == dist[pid] and flag < open_end[pid]):
                    dist[pid] = nd
                    open_end[pid] = flag
                    heapq.heappush(heap, (nd, flag, pid))
        return dist, open_end
