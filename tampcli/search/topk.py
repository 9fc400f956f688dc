"""Ranked plans: a lazy generator of plans in non-decreasing cost, exact.

`TopK(task)` yields every plan of the task, cheapest first: standard top-k
(`loopless=False`, what K* computes: a plan may pass a state twice) or
loopless (no state twice in a plan, what `solve` wants first; `revisits=1`:
no state passed a third time, what it wants next, a regrasp being a pick, a
place and the same pick again). `forbid_prefix`
removes every later plan that starts with some operator names.

Method. A bounded A*-like exploration (topk_graph.py) grows the explored part
of the state space with an admissible h, layer by layer of g + h; on it,
`distances()` gives every known state s a lower bound d(s) on the cost to a
goal of *every* plan from s: the exact cheapest cost to a goal while staying
in the expanded part, and, through a state t not expanded yet, the cost to t
plus t's admissible h. Partial paths are then enumerated best-first on
f = g + d(end). Why the order is exact:

- d is admissible for every plan, so each prefix q of a plan p has
  f(q) <= cost(p).
- The queue holds, for every plan not yet output, an entry standing for one
  of its prefixes (or for an earlier sibling edge of one, see below) whose f
  is <= the plan's cost. So when a finished plan of cost c is popped (f = c,
  since d = 0 at an expanded goal), no plan cheaper than c is left: plans
  come out in non-decreasing cost, every one of them, ties in a fixed order.
- A popped path whose end is not expanded yet cannot be extended: the
  enumeration stops there, the exploration goes further and the enumeration
  restarts, skipping the plans already out (by cost below the current bound,
  by identity at it). Each retry doubles the exploration's budget; once the
  layer g + h <= B is fully expanded, a path that reaches an unexpanded state
  t has f >= g(t) + h(t) > B, so the enumeration up to B completes. Until a
  goal state is expanded there is no plan to enumerate: the exploration
  alone completes each layer and raises B to the smallest g + h left.
- Inside the expanded part d is exact: a popped path extends to a plan of
  cost exactly f, little work is wasted. At equal f, continuations already
  known to reach a goal come before those through unexpanded states, so the
  last layer is often explored only in part (K* gets the same effect by
  interleaving A* and Eppstein's algorithm). Loopless mode: d can be too
  optimistic when the cheapest continuation revisits a state; it is still
  admissible, so still exact, with some dead branches.

Children are not all queued at once: the successor edges of each state are
sorted by c + d(next), and popping the entry for edge i of a path queues
edge i + 1 of the same path (its f is no smaller) and edge 0 of the
extended path. The queue grows by at most two entries per pop.

When the queue's smallest f exceeds the bound B, all plans of cost <= B are
out; B is raised to the smallest value that can matter (the next f in the
queue, or the smallest g + h still to explore). Once the whole reachable
space is explored, B is infinite. With zero-cost cycles, infinitely many
plans can share a cost: the generator then stays in that cost forever, as it
must. With fractional costs, two plans whose costs differ only by float
rounding (the same costs summed in another order) may come out either way.
"""

from __future__ import annotations

import heapq
import itertools
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass

from tampcli.errors import UnsupportedFeatureError, UsageError
from tampcli.search.topk_graph import INF, BoundedGraph, TimeUp
from tampcli.task.task import Operator, Task


@dataclass(frozen=True)
class Plan:
    operators: tuple[Operator, ...]
    cost: float

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(op.name for op in self.operators)


def default_heuristic(task: Task) -> Callable[[frozenset], float]:
    """LM-cut with its landmarks when the task allows it, else h_max (both admissible)."""
    from tampcli.search.heuristics import HMax
    from tampcli.search.topk_landmarks import LandmarkCut

    try:
        return LandmarkCut(task)
    except UnsupportedFeatureError:
        return HMax(task)


class _Path:
    """A partial path: a chain of (operator, state) back to the initial state."""

    __slots__ = ("parent", "op", "sid", "g", "trie", "trie_version")

    def __init__(self, parent, op, sid, g):
        self.parent, self.op, self.sid, self.g = parent, op, sid, g
        self.trie, self.trie_version = None, -1

    def operators(self) -> list[int]:
        ops, node = [], self
        while node.parent is not None:
            ops.append(node.op)
            node = node.parent
        ops.reverse()
        return ops

    def visits(self, sid: int, times: int = 1) -> bool:
        """Passes state `sid` at least `times` times."""
        node = self
        while node is not None:
            if node.sid == sid:
                times -= 1
                if times == 0:
                    return True
            node = node.parent
        return False


@dataclass(frozen=True)
class _Unexpanded:
    """An enumeration stopped at this state: the exploration must go further."""

    sid: int


_FORBIDDEN = "forbidden"  # marks a trie node whose prefix is forbidden
_FIRST_CHUNK = 64  # expansions before a layer's first enumeration; doubled on each retry


class TopK:
    """Iterator of `Plan`s in non-decreasing cost (see the module docstring)."""

    def __init__(self, task: Task, loopless: bool = False, time_limit: float | None = None,
                 heuristic: Callable[[frozenset], float] | None = None, revisits: int = 0):
        """`time_limit`: seconds from now for all the plans together (then the
        iteration ends and `status` is "limit"). `heuristic`: any admissible
        one (default: LM-cut with landmarks, or h_max with conditional effects).
        `revisits` (loopless only): how many times more than once a plan may pass
        a state.
        """
        if time_limit is not None and not time_limit > 0:
            raise UsageError(f"the time limit must be positive, got {time_limit}",
                             key="--time-limit")
        self.task, self.loopless, self.revisits = task, loopless, revisits
        self._start = time.perf_counter()
        self._deadline = None if time_limit is None else self._start + time_limit
        self._graph = BoundedGraph(task, heuristic or default_heuristic(task), self._check_time)
        self._trie: dict = {}
        self._trie_version = 0
        self._names = [op.name for op in task.operators]
        self.stats: dict = {"plans": 0, "phases": 0, "pops": 0, "pushes": 0,
                            "status": "running"}
        self._plans = self._generate()

    def __iter__(self) -> Iterator[Plan]:
        return self

    @property
    def status(self) -> str:
        """"running" (more plans may come), "exhausted" (no other plan) or "limit" (time)."""
        return self.stats["status"]

    def __next__(self) -> Plan:
        return next(self._plans)

    def forbid_prefix(self, names: tuple[str, ...]) -> None:
        """Never yield (nor expand) a later plan whose operator names start with `names`."""
        node = self._trie
        for name in names:
            if _FORBIDDEN in node:
                return  # a shorter prefix already forbids it
            node = node.setdefault(name, {})
        node.clear()
        node[_FORBIDDEN] = True
        self._trie_version += 1

    # ------------------------------------------------------------ internals

    def _check_time(self) -> None:
        if self._deadline is not None and time.perf_counter() > self._deadline:
            raise TimeUp

    def _generate(self) -> Iterator[Plan]:
        graph = self._graph
        done = -INF  # every plan of cost <= done has been output
        try:
            bound = graph.next_key()
            while bound < INF:
                yielded: set = set()  # plans of cost in (done, bound] already out
                chunk = _FIRST_CHUNK
                while True:
                    finished = graph.explore(bound, chunk)
                    if graph.complete:
                        bound = INF
                    if not graph.goals:
                        # no goal expanded, so no plan of cost <= bound: nothing to
                        # enumerate (the full distances would be wasted on it)
                        if not finished:
                            continue
                        next_f = INF
                        break
                    self.stats["phases"] += 1
                    next_f = yield from self._enumerate(*graph.distances(), bound, done,
                                                        yielded)
                    if not isinstance(next_f, _Unexpanded):
                        break
                    if finished:  # only float rounding can get here: expand that one
                        graph.expand_now(next_f.sid)
                    chunk *= 2
                done = bound
                bound = min(next_f, graph.next_key())
            self.stats["status"] = "exhausted"
        except TimeUp:
            self.stats["status"] = "limit"
        finally:
            self._update_stats()

    def _enumerate(self, dist: list[float], open_end: bytearray, bound: float, done: float,
                   yielded: set):
        """Yield the plans of cost in (done, bound] not in `yielded`; return the next f
        beyond bound, or _Unexpanded on reaching a state not expanded yet."""
        graph, task_ops = self._graph, self.task.operators
        costs, succ, goal = graph.costs, graph.succ, graph.goal
        # per state, its edges (c + d(next), ends unexpanded, d(next), op, next), sorted:
        # at equal cost, continuations known to reach a goal come first
        edges: dict[int, list[tuple[float, int, float, int, int]]] = {}

        def out(sid: int) -> list[tuple[float, int, float, int, int]]:
            found = edges.get(sid)
            if found is None:
                found = sorted((costs[op] + dist[nid], open_end[nid], dist[nid], op, nid)
                               for op, nid in succ[sid] if dist[nid] < INF)
                edges[sid] = found
            return found

        counter = itertools.count()
        queue: list = []
        stats = self.stats

        def push(path: _Path, i: int) -> None:
            lst = out(path.sid)
            if self.loopless:
                while i < len(lst) and path.visits(lst[i][4], 1 + self.revisits):
                    i += 1
            if i < len(lst):
                step, flag, rest, _, _ = lst[i]
                heapq.heappush(queue, (path.g + step, flag, rest, next(counter), path, i))
                stats["pushes"] += 1

        root = _Path(None, -1, 0, 0.0)
        if dist[0] < INF:
            heapq.heappush(queue, (dist[0], open_end[0], dist[0], next(counter), None, -1))
        while queue and queue[0][0] <= bound:
            _, _, _, _, parent, i = heapq.heappop(queue)
            stats["pops"] += 1
            if stats["pops"] % 1024 == 0:
                self._check_time()
            if parent is None:
                path = root
            else:
                push(parent, i + 1)
                _, _, _, op, nid = edges[parent.sid][i]
                path = _Path(parent, op, nid, parent.g + costs[op])
            if self._forbidden(path):
                continue
            if succ[path.sid] is None:
                return _Unexpanded(path.sid)
            if goal[path.sid] and path.g > done:
                ops = tuple(path.operators())
                if ops not in yielded:
                    yielded.add(ops)
                    self.stats["plans"] += 1
                    self._update_stats()
                    yield Plan(tuple(task_ops[o] for o in ops), path.g)
            push(path, 0)
        return queue[0][0] if queue else INF

    def _forbidden(self, path: _Path) -> bool:
        """Is a forbidden prefix a prefix of `path`? (trie pointer cached per path)"""
        if not self._trie:
            return False
        return self._trie_node(path) is _FORBIDDEN

    def _trie_node(self, path: _Path):
        """The trie node of `path`'s names, None once off the trie, or _FORBIDDEN."""
        version = self._trie_version
        chain = []
        node = path
        while node is not None and node.trie_version != version:
            chain.append(node)
            node = node.parent
        for p in reversed(chain):
            if p.parent is None:
                t = self._trie
            else:
                above = p.parent.trie
                t = above if above is None or above is _FORBIDDEN else above.get(
                    self._names[p.op])
            if t is not None and t is not _FORBIDDEN and _FORBIDDEN in t:
                t = _FORBIDDEN
            p.trie, p.trie_version = t, version
        return path.trie

    def _update_stats(self) -> None:
        g = self._graph
        self.stats.update(states=len(g.states), expansions=g.expansions,
                          evaluations=g.evaluations,
                          seconds=round(time.perf_counter() - self._start, 4))
