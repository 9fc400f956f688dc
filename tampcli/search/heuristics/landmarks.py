"""The landmark-count heuristic of LAMA (Richter & Westphal 2010), on fact landmarks
found by back-chaining through the relaxed planning graph.

Landmarks (facts every plan makes true at some point): the goal facts; then,
for each landmark L not true initially, the preconditions shared by all of
L's *first achievers* (the achievers applicable in the relaxed exploration
from the initial state that never makes L true) are landmarks, ordered
greedy-necessarily before L. This is the shared-precondition part of RHW
landmarks, without disjunctive or domain-transition-graph landmarks.
Auxiliary relaxed facts (`or` nodes, derived facts, the goal fact) are
chained through but are not landmarks themselves: a state does not hold them.

The count is path-dependent: a search reports each state's first parent with
`progress(parent, state)`; the state's reached landmarks are its parent's
plus those true in it (for a state never reported: those true in it and
those ordered before them). h = landmarks not reached, plus reached ones needed
again (a goal false now, or a landmark false now that must hold right before
a landmark ordered after it that is not reached yet). Every landmark counts
1, as in LAMA's first search.
"""

from __future__ import annotations

from tampcli.search.heuristics.relaxed import INF, RelaxedTask
from tampcli.task.task import Task


class LandmarkCount:
    admissible = False

    def __init__(self, task: Task):
        self.task = task
        r = RelaxedTask(task)
        real = [f not in task.derived for f in range(len(task.facts))]
        real += [False] * (r.n_facts - len(real))
        achievers: list[list[int]] = [[] for _ in range(r.n_facts)]
        for a, adds in enumerate(r.add):
            for q in adds:
                achievers[q].append(a)
        landmarks, before, unreachable = _backchain(r, achievers, real, task.init)
        self.facts = tuple(landmarks)
        self.bit = {f: 1 << i for i, f in enumerate(self.facts)}
        self.all = (1 << len(self.facts)) - 1
        goal_facts = task.goal.pos
        self.goal_mask = sum(self.bit[f] for f in self.facts if f in goal_facts)
        # per landmark: the mask of the landmarks it is greedy-necessary for
        self.children = [0] * len(self.facts)
        for parent, child in before:
            self.children[landmarks[parent]] |= self.bit[child]
        self.orderings = len(before)
        # per landmark: the landmarks ordered (transitively) before it
        self.ancestors = [0] * len(self.facts)
        parents: dict[int, list[int]] = {}
        for parent, child in before:
            parents.setdefault(landmarks[child], []).append(landmarks[parent])
        for i in range(len(self.facts)):
            mask, todo = 0, list(parents.get(i, ()))
            while todo:
                j = todo.pop()
                if not mask & (1 << j):
                    mask |= 1 << j
                    todo.extend(parents.get(j, ()))
            self.ancestors[i] = mask
        # a landmark no relaxed plan from the initial state reaches: a state
        # that still needs it is a dead end (all are when the goal is one)
        self.dead = sum(self.bit[f] for f in unreachable if f in self.bit)
        self.unsolvable = r.goal in unreachable
        self.reached: dict = {task.init: self.true_in(task.init)}

    def true_in(self, state) -> int:
        bit = self.bit
        mask = 0
        for f in state:
            b = bit.get(f)
            if b:
                mask |= b
        return mask

    def progress(self, parent, state) -> None:
        """Record `state`'s reached landmarks when it is first reached from `parent`."""
        if state not in self.reached:
            self.reached[state] = self.reached.get(parent, 0) | self.true_in(state)

    def __call__(self, state) -> float:
        true = self.true_in(state)
        reached = self.reached.get(state)
        if reached is None:
            # a state no search step led to: what is ordered before a
            # landmark that holds has been reached on the way to it
            reached = true
            rest = true
            while rest:
                low = rest & -rest
                reached |= self.ancestors[low.bit_length() - 1]
                rest ^= low
        if self.unsolvable or self.dead & ~true:
            return INF
        h = bin(self.all & ~reached).count("1")
        needed = reached & ~true
        if needed:
            again = needed & self.goal_mask
            rest = needed & ~again
            children = self.children
            while rest:
                low = rest & -rest
                if children[low.bit_length() - 1] & ~reached:
                    again |= low
                rest ^= low
            h += bin(again).count("1")
        return float(h)


def _backchain(r: RelaxedTask, achievers, real, init) -> tuple[dict[int, int], list, set]:
    """Landmark facts (fact -> index), orderings (parent fact, child fact), and the
    landmarks (auxiliary ones too) unreachable from `init` in the relaxation."""
    unreachable: set[int] = set()
    landmarks: dict[int, int] = {}
    targets: dict[int, frozenset[int]] = {r.goal: frozenset()}
    orderings: set[tuple[int, int]] = set()
    queue = [r.goal]
    seen = {r.goal}
    while queue:
        fact = queue.pop()
        if fact in init:
            continue
        reached = _reachable_without(r, fact, init)
        first = [a for a in achievers[fact] if all(reached[p] for p in r.pre[a])]
        if not first:
            unreachable.add(fact)
            continue
        shared = set(r.pre[first[0]])
        for a in first[1:]:
            shared.intersection_update(r.pre[a])
        # orderings go to the nearest real landmarks after `fact`
        after = frozenset({fact}) if real[fact] else targets[fact]
        for p in shared:
            if real[p]:
                orderings.update((p, child) for child in after)
                if p not in landmarks:
                    landmarks[p] = len(landmarks)
            else:
                targets[p] = targets.get(p, frozenset()) | after
            if p not in seen:
                seen.add(p)
                queue.append(p)
    return landmarks, sorted(orderings), unreachable


def _reachable_without(r: RelaxedTask, banned: int, init) -> bytearray:
    """Facts relaxed-reachable from `init` by actions that do not add `banned`."""
    reached = bytearray(r.n_facts)
    unsat = r.pre_count[:]
    stack = []
    for f in init:
        reached[f] = 1
        stack.append(f)
    for a in r.no_pre:
        if banned not in r.add[a]:
            for q in r.add[a]:
                if not reached[q]:
                    reached[q] = 1
                    stack.append(q)
    pre_of, adds = r.pre_of, r.add
    while stack:
        f = stack.pop()
        for a in pre_of[f]:
            unsat[a] -= 1
            if unsat[a] == 0:
                add = adds[a]
                if banned in add:
                    continue
                for q in add:
                    if not reached[q]:
                        reached[q] = 1
                        stack.append(q)
    return reached
