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
when the child comes out of the queue at a key <= B, starting from those
landmarks (from the parent that gave the best bound).
"""

from __future__ import annotations

import heapq
from collections.abc import Callable

from tampcli.task.task import Task

INF = float("inf")
_NOT_INHERITED = (0.0,)


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
        # of states not evaluated yet: (value, a parent's landmarks, op from it)
        self._inherit: dict[int, tuple[float, list, int]] = {}
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
        self.goals = 0  # expanded goal states
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
        costs = self.costs
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
                if self.expansions % 256 == 0:
                    self.check_time()
                self._expand(sid, g, h)
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
        self._expand(sid, self.g[sid], h)

    def _expand(self, sid: int, g: float, h: float) -> None:
        """Generate the successors, each queued with the best bound known from here.

        With landmarks, a successor also keeps those it inherits (the ones its
        operator is not in), for LM-cut to start from (see topk_landmarks.py).
        """
        self.expansions += 1
        state = self.states[sid]
        if self.task.is_goal(state):
            self.goal[sid] = True
            self.goals += 1
        index, costs = self.op_index, self.costs
        marked = self._landmarks.pop(sid, None)
        succ = []
        if marked is None:
            for op, nxt in self.task.successors(state):
                o = index[id(op)]
                succ.append((o, self._id(nxt, g + costs[o], h - costs[o])))
        else:
            total, found = marked
            charged: dict[int, float] = {}
            for m, ops in found:
                for o in ops:
                    charged[o] = charged.get(o, 0.0) + m
            inherit, hs, partial = self._inherit, self.h, self._partial
            for op, nxt in self.task.successors(state):
                o = index[id(op)]
                c = costs[o]
                kept = total - charged.get(o, 0.0)
                nid = self._id(nxt, g + c, kept if kept > h - c else h - c)
                # the most valuable inheritance wins; none once LM-cut has run on it
                if (kept > 0.0 and hs[nid] is None and nid not in partial
                        and kept > inherit.get(nid, _NOT_INHERITED)[0]):
                    inherit[nid] = (kept, found, o)
                succ.append((o, nid))
        self.succ[sid] = tuple(succ)

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
            inherited = self._inherit.pop(sid, None)
            if inherited is not None:
                _, found, op = inherited
                inherited = [lm for lm in found if op not in lm[1]]
            value, found, rest = self._with_landmarks(state, budget, self._partial.pop(sid, None),
                                                      inherited or ())
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
