"""Skeletons ordered by what geometry has learned: obstructions flow back to the task.

A domain often says nothing of what is in the way: `(in ?b ?r)` with no
`clear` and no capacity. Geometry finds out: placing `a` in the goal
overlaps `b`, which still stands where it started; the way to `a` runs
through `c`. Each such finding is a `Blocker` (the body in the way, the
ground action it blocked), and becomes a precondition over the task: that
action needs the body *moved* first. The task is compiled anew with one
fact `(moved b)` per blocking body, added by every action that moves `b`,
and required by the actions `b` blocked; the top-k enumeration restarts on
it, so the next skeletons are those that clear the obstruction.

Sound, not complete on its own: a learned precondition is a guess (a body
moved out of the way may come back elsewhere; it may have blocked only in
the pose the optimizer happened to choose). So it orders skeletons, never
filters them: when the compiled task has no skeleton left, the plain task's
skeletons follow, each drawn once. `lower_bound()` is proved on symbolic
cost whatever was learned: the cheapest skeleton of the *plain* task not
drawn yet.

Actions that serve nothing are not worth an NLP: a skeleton made of a
solved one plus more actions ("superseded": its symbolic cost is higher, and its
extra stops can lower the motion's cost only by splitting it, README "Objective
and bounds"), or of
an evaluated one that already meets everything learned plus more actions
("redundant": the extras are symbolically useless given what is known), is
deferred until every other skeleton has been drawn, unless its extra actions
move a body the shorter one leaves alone (that may clear what geometry found
in the way without naming it). Deferred is not lost: the bound counts them as
not drawn.
"""

from __future__ import annotations

import dataclasses
import heapq
import math
from collections import deque
from collections.abc import Callable, Iterator

from tampcli.search import learned_task
from tampcli.search.learned_task import MOVED, PROVED, Blocker, compile_task, is_subsequence
from tampcli.task.task import Operator, Task

__all__ = ["MOVED", "PROVED", "Blocker", "LearningSource", "compile_task"]

# Deferred skeletons in a row before the cheapest deferred one is drawn anyway: past
# the few skeletons that clear an obstruction, a ranked enumeration yields mostly
# padded copies of them (tens of thousands a minute on a pen with three blockers,
# measured), and branch and bound should not wait for the enumeration to get past them.
MAX_DEFERRED_IN_A_ROW = 100
# Plans of the compiled task in a row that pass a state of the task twice before the
# learned enumeration is given up (the plain task's skeletons follow, as when it has
# none left; the next lesson starts it again). A lesson no loopless plan meets (blind31
# p01: "tin moved before (pick g1 counter)", the tin fits no grasp and no other place)
# leaves the compiled task only plans that move it and put it back: 1.3 million of
# them in 83 s, to the time limit, and no skeleton drawn. About a second of them here.
MAX_LOOPING_IN_A_ROW = 20_000


class LearningSource:
    """A SkeletonSource (branch and bound's) that learns from geometric failures.

    `make_topk(task)` builds a ranked plan iterator with `forbid_prefix`
    (search.topk.TopK); `moves(op)` names the bodies an operator moves.
    `loopless`: the plain enumeration passes no state twice; the compiled
    task's states tell more apart (what was moved), so its plans are held
    to the same rule on the plain task's states.

    `make_regrasps(task)`: the ranked plans that may pass a state twice, none
    three times (TopK's `revisits=1`), enumerated once every loopless skeleton has been
    drawn and none was feasible: a regrasp (pick, place, pick the same object
    again with another grip) passes the state "holding it" twice, and is the
    only way to move an object that no single grip takes from start to goal
    (a side grasp out of a low nook, a top grasp into a deep bin). Until then
    `lower_bound` counts them as not drawn (each costs at least the cheapest
    plan: its loop taken out, it is a plan)."""

    def __init__(self, task: Task, make_topk: Callable[[Task], object],
                 moves: Callable[[Operator], frozenset[str]], loopless: bool = True,
                 make_regrasps: Callable[[Task], object] | None = None):
        self.task, self._make, self._moves = task, make_topk, moves
        self._base = task  # as given: require_moved compiles its proofs into a copy
        self.proved: frozenset[Blocker] = frozenset()  # preconditions require_moved took in
        self.loopless = loopless
        self.revisits = 0  # times more than once a drawn plan may pass a state
        self.impossible: frozenset[str] = frozenset()  # operators forbid_operators took out
        self._make_regrasps = make_regrasps
        self._cheapest = None  # the cost of the task's cheapest plan, once pulled
        self._by_name = {op.name: op for op in task.operators}
        self.blockers: frozenset[Blocker] = frozenset()
        self.suspects: frozenset[str] = frozenset()  # operators `suspect` put last
        self._compiled, self._compiled_ops = task, self._by_name
        self._plain = make_topk(task)
        self._plain_queue: deque = deque()  # plain plans pulled for the bound, not yet drawn
        self._ahead = None  # the next skeleton, found by waiting_on_results, not yet drawn
        self._plain_done = False
        self._learned = None  # the compiled task's iterator while it has skeletons
        self._drawn: set[tuple[str, ...]] = set()  # given to branch and bound
        self._considered: set[tuple[str, ...]] = set()  # drawn or deferred
        self._deferred: list = []  # heap of (cost, order, plan): redundant given what is known
        self._evaluated: list[tuple[str, ...]] = []
        self._fits: dict[tuple[str, ...], bool] = {}  # evaluated plan -> valid in _compiled
        self._solved: list[tuple[str, ...]] = []
        self._forbidden: list[tuple[str, ...]] = []
        self.stats = dict(learned=0, superseded=0, redundant=0, from_learned=0, proved=0,
                          suspects=0, given_up=0)

    # ------------------------------------------------------------ what bnb tells it

    def learn(self, blocker: Blocker, *more: Blocker) -> bool:
        """Take findings in; True when one is new (the enumeration restarts, once). A
        finding that a skeleton already found feasible contradicts (it does the action
        with the body not moved before it) is not taken: blind36 p01 learned "block-blue
        moved before (place block-red bin)" from a failure after #1 had put block-red
        in the bin beside block-blue, and every plan without that move waited behind
        the 8-action ones for the rest of the run."""
        new = frozenset(b for b in (blocker, *more) if not self._contradicted(b)) \
            - self.blockers
        if not new:
            return False
        self.blockers = self.blockers | new
        self.stats["learned"] += len(new)
        self._recompile()
        self._restart(plain=False)
        return True

    def suspect(self, name: str) -> bool:
        """An operator that failed in a way that may not depend on where it stands in
        a skeleton (a push into a wall): the skeletons without it come first. An
        ordering, like `learn`: the plain enumeration still yields the others. True
        when it is new (the learned enumeration restarts)."""
        if name in self.suspects or name not in self._by_name:
            return False
        self.suspects = self.suspects | {name}
        self.stats["suspects"] = len(self.suspects)
        self._recompile()
        self._restart(plain=False)
        return True

    def _recompile(self) -> None:
        """The task with what was learned, anew (the task or the findings changed)."""
        compiled = compile_task(self.task, self.blockers, self._moves)
        self._compiled = dataclasses.replace(compiled, operators=tuple(
            op for op in compiled.operators if op.name not in self.suspects))
        self._compiled_ops = {op.name: op for op in self._compiled.operators}
        self._fits.clear()

    def _restart(self, plain: bool) -> None:
        """The learned enumeration (and the plain one when `plain`) starts again, the
        forbidden prefixes still forbidden."""
        self._unpeek()
        if plain:
            self._plain, self._plain_done = self._make(self.task), False
        self._learned = self._make(self._compiled) if self.blockers or self.suspects else None
        for names in self._forbidden:
            if plain:
                self._plain.forbid_prefix(names)
            if self._learned is not None:
                self._learned.forbid_prefix(names)

    def _contradicted(self, blocker: Blocker) -> bool:
        """Whether a skeleton found feasible does `blocker.action` with `blocker.body`
        not moved by any action before it."""
        for names in self._solved:
            if blocker.action not in names:
                continue
            before = names[:names.index(blocker.action)]
            if not any(blocker.body in self._moves(self._by_name[n])
                       for n in before if n in self._by_name):
                return True
        return False

    def solved(self, names: tuple[str, ...]) -> None:
        """A skeleton found feasible: its supersequences are not worth an NLP."""
        self._solved.append(tuple(names))

    def forbid_operators(self, names: frozenset[str]) -> None:
        """Operators proved infeasible in every skeleton (no grasp of an object fits):
        gone from the task, the enumerations start again without them. The bound
        stays proved: no feasible skeleton is lost."""
        names = frozenset(names) & frozenset(op.name for op in self.task.operators)
        if not names:
            return
        self.impossible |= names
        self.task = dataclasses.replace(self.task, operators=tuple(
            op for op in self.task.operators if op.name not in names))
        self._recompile()
        self._restart(plain=True)

        def uses(plan) -> bool:
            return any(name in names for name in plan.names)

        self._plain_queue = deque(p for p in self._plain_queue if not uses(p))
        self._deferred = [d for d in self._deferred if not uses(d[2])]
        heapq.heapify(self._deferred)

    def require_moved(self, blockers: frozenset[Blocker]) -> None:
        """Preconditions proved for every skeleton (a push that cannot move its object
        from its start pose: the object must have been moved before it), compiled into
        the task itself: no skeleton that breaks one is enumerated any more, and the
        bound stays proved (only infeasible skeletons are left out). Unlike `learn`,
        which orders, this filters."""
        new = frozenset(blockers) - self.proved
        if not new:
            return
        self.proved |= new
        self.stats["proved"] = len(self.proved)
        base = dataclasses.replace(self._base, operators=tuple(
            op for op in self._base.operators if op.name not in self.impossible))
        self.task = compile_task(base, self.proved, self._moves, PROVED)
        self._recompile()
        self._restart(plain=True)
        self._plain_queue = deque(p for p in self._plain_queue if self._valid(p.names))
        self._deferred = [d for d in self._deferred if self._valid(d[2].names)]
        heapq.heapify(self._deferred)

    def _valid(self, names: tuple[str, ...]) -> bool:
        """The plan reaches the goal in the (proved-compiled) task."""
        ops = {op.name: op for op in self.task.operators}
        state = self.task.init
        for name in names:
            op = ops.get(name)
            if op is None or not op.pre.holds(self.task.closure(state)):
                return False
            state = self.task.apply(state, op)
        return self.task.is_goal(state)

    def forbid_prefix(self, names: tuple[str, ...]) -> None:
        self._unpeek()
        self._forbidden.append(tuple(names))
        self._plain.forbid_prefix(names)
        if self._learned is not None:
            self._learned.forbid_prefix(names)
        self._plain_queue = deque(p for p in self._plain_queue
                                  if p.names[:len(names)] != tuple(names))
        self._deferred = [d for d in self._deferred if d[2].names[:len(names)] != tuple(names)]
        heapq.heapify(self._deferred)

    # ------------------------------------------------------------ what it gives

    @property
    def scope(self) -> str:
        """Which skeletons this source yields, in words (for a search's last message)."""
        words = "loopless ones"
        if self._make_regrasps is not None or self.revisits:
            words += (", then, none being feasible, those passing a symbolic state twice at "
                      "most (a regrasp)")
        gone = sorted(self.impossible)
        if gone:
            words += (f"; less every skeleton with one of {len(gone)} action(s) proved "
                      f"impossible in any skeleton ({', '.join(gone[:3])}"
                      f"{' ...' if len(gone) > 3 else ''})")
        return words

    def proof_names(self) -> tuple[str, ...]:
        """The proofs `proofs` counts, in words: each with what proves it where known."""
        return tuple(sorted(b.words() for b in self.proved)) + tuple(
            f"{name} is impossible in any skeleton" for name in sorted(self.impossible))

    @property
    def proofs(self) -> int:
        """Geometric proofs compiled into the task: preconditions proved for every
        skeleton (`require_moved`) and actions proved impossible in any."""
        return len(self.proved) + len(self.impossible)

    @property
    def status(self) -> str:
        return getattr(self._plain, "status", "running")

    def lower_bound(self) -> float:
        """Proved: no skeleton not yet drawn costs less (symbolic cost). Deferred
        skeletons count as not drawn: they may still come."""
        while self._plain_queue and self._plain_queue[0].names in self._drawn:
            self._plain_queue.popleft()
        while not self._plain_queue:
            if not self._pull_plain():
                break
            while self._plain_queue and self._plain_queue[0].names in self._drawn:
                self._plain_queue.popleft()
        candidates = [self._plain_queue[0].cost] if self._plain_queue else []
        candidates += [self._ahead.cost] if self._ahead is not None else []
        candidates += [cost for cost, _, _ in self._deferred[:1]]
        if self._regrasps_may_come() and self._cheapest is not None:
            candidates.append(self._cheapest)
        return min(candidates, default=math.inf)

    def _regrasps_may_come(self) -> bool:
        return self._make_regrasps is not None and not self._solved

    def _start_regrasps(self) -> bool:
        """Every loopless skeleton drawn, none feasible: on to those passing one state
        twice (the loopless ones among them are skipped: considered already)."""
        if not self._regrasps_may_come():
            return False
        self._make, self._make_regrasps = self._make_regrasps, None
        self.revisits = 1
        self._restart(plain=True)
        return True

    def __iter__(self) -> Iterator:
        return self

    def __next__(self):
        plan, self._ahead = self._ahead, None
        plan = self._fresh() if plan is None else plan
        if plan is not None:
            return self._draw(plan)
        if self._deferred:
            return self._draw(heapq.heappop(self._deferred)[2])
        if self._start_regrasps():
            return next(self)
        raise StopIteration

    def waiting_on_results(self) -> bool:
        """Whether what comes next (learned orders, a deferred skeleton, the regrasps
        only no feasible one calls for) depends on how the ones drawn end, every
        loopless one being drawn or deferred: a parallel search takes their results
        first (arm-pick-place p03, --jobs 2: 18 regrasps drawn while its two
        loopless skeletons, both feasible, were out)."""
        if self._ahead is None:
            self._ahead = self._fresh()
        return self._ahead is None

    def _unpeek(self) -> None:
        """The skeleton waiting_on_results found goes back to the enumeration."""
        if self._ahead is not None:
            self._considered.discard(self._ahead.names)
            self._plain_queue.appendleft(self._ahead)
            self._ahead = None

    def _fresh(self):
        """The next skeleton worth drawing now (deferring others), or None."""
        for _ in range(MAX_DEFERRED_IN_A_ROW):
            plan = self._next_learned() or self._next_plain()
            while plan is not None and plan.names in self._considered:
                plan = self._next_learned() or self._next_plain()
            if plan is None:
                return None
            self._considered.add(plan.names)
            why = self._why_defer(plan.names)
            if why is None:
                return plan
            self.stats[why] += 1
            heapq.heappush(self._deferred, (plan.cost, len(self._considered), plan))
        return None

    def _draw(self, plan):
        self._drawn.add(plan.names)
        self._evaluated.append(plan.names)
        return plan

    def _why_defer(self, names: tuple[str, ...]) -> str | None:
        """"superseded": a solved skeleton plus more actions (extra actions that serve
        nothing symbolically);
        "redundant": an evaluated skeleton that already meets everything learned,
        plus actions; both come last, after every other skeleton."""
        if any(is_subsequence(s, names) for s in self._solved):
            return "superseded"
        for other in self._evaluated:
            if len(other) < len(names) and is_subsequence(other, names) \
                    and self._meets_learned(other) and self._moves_nothing_new(other, names):
                return "redundant"
        return None

    def _moves_nothing_new(self, other: tuple[str, ...], names: tuple[str, ...]) -> bool:
        """Do the actions `names` adds to `other` (a subsequence of it) before `other`'s
        last action move only bodies `other` moves too? Moving another body first can
        clear what made `other` fail even where nothing was learned of it (a pen of
        four blockers: the final NLP's worst row named a neighbour, not the third and
        fourth blocker), so that is never redundant; what comes after is."""
        moved = set().union(*(self._moves(self._by_name[n]) for n in other))
        at, last = 0, 0
        for i, name in enumerate(names):
            if at < len(other) and name == other[at]:
                at, last = at + 1, i
        return all(self._moves(self._by_name[n]) <= moved for n in names[:last])

    def _meets_learned(self, names: tuple[str, ...]) -> bool:
        """The plan is valid in the compiled task: it moves every known blocker first."""
        if names not in self._fits:
            task, state, ok = self._compiled, self._compiled.init, True
            for name in names:
                op = self._compiled_ops.get(name)
                if op is None or not op.pre.holds(task.closure(state)):
                    ok = False
                    break
                state = task.apply(state, op)
            self._fits[names] = ok and task.is_goal(state)
        return self._fits[names]

    def _next_learned(self):
        looping = 0
        while self._learned is not None:
            try:
                plan = next(self._learned)
            except StopIteration:
                self._learned = None
                return None
            plan = self._plain_version(plan)
            if self.loopless and self._loops(plan):
                looping += 1
                if looping >= MAX_LOOPING_IN_A_ROW:
                    self._learned = None
                    self.stats["given_up"] += 1
                    return None
                continue
            if plan.names not in self._considered:
                self.stats["from_learned"] += 1
                return plan
        return None

    def _loops(self, plan) -> bool:
        return learned_task.passes_twice(self._base, plan, 1 + self.revisits)

    def _plain_version(self, plan):
        """The plan with the task's own operators (the compiled ones carry `moved` facts)."""
        return dataclasses.replace(plan, operators=tuple(self._by_name[op.name]
                                                         for op in plan.operators))

    def _next_plain(self):
        while self._plain_queue or self._pull_plain():
            plan = self._plain_queue.popleft()
            if plan.names in self._considered:
                continue
            # A proved precondition's fact tells states apart that the task does not:
            # its enumeration's plans are held to the task's states, as learned ones are.
            if self.proved and self.loopless and self._loops(self._plain_version(plan)):
                continue
            return plan
        return None

    def _pull_plain(self) -> bool:
        if self._plain_done:
            return False
        try:
            plan = next(self._plain)
        except StopIteration:
            self._plain_done = True
            return False
        if self._cheapest is None:
            self._cheapest = plan.cost
        self._plain_queue.append(plan)
        return True
