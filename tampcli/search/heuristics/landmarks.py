"""The landmark-count heuristic of LAMA (Richter & Westphal 2010), on fact landmarks
found by back-chaining through the relaxed planning graph.

Landmarks (facts, or sets of facts, every plan makes true at some point): the goal facts; then,
for each landmark L not true initially, the preconditions shared by all of
L's *first achievers* (the achievers applicable in the relaxed exploration
from the initial state that never makes L true) are landmarks, ordered
greedy-necessarily before L; so is, for each predicate that every first
achiever needs a fact of, the disjunction of those facts (when it has 2 to 4
facts, none true initially, none that is a landmark alone or in another
disjunction, as in Fast Downward's RHW): one of
them is made true by every plan. Disjunctive landmarks are back-chained like
the others. This is RHW's back-chaining (Richter, Helmert & Westphal 2008)
without its domain-transition-graph landmarks, with predicates in place of
SAS+ variables.
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
        predicate = [name[1:].split(" ", 1)[0].rstrip(")") for name in task.facts]
        found = _Backchain(r, achievers, real, predicate, task.init)
        landmarks = found.landmarks
        self.landmarks: tuple[frozenset[int], ...] = tuple(landmarks)
        n = len(self.landmarks)
        # a fact may belong to several landmarks (disjunctive ones)
        self.bit = [0] * len(task.facts)  # per fact: the landmarks it belongs to
        for i, node in enumerate(self.landmarks):
            for f in node:
                self.bit[f] |= 1 << i
        self.all = (1 << n) - 1
        goal_facts = task.goal.pos
        self.goal_mask = sum(1 << i for i, node in enumerate(self.landmarks)
                             if len(node) == 1 and node <= goal_facts)
        # per landmark: the mask of the landmarks it is greedy-necessary for
        self.children = [0] * n
        parents: dict[int, list[int]] = {}
        for parent, child in found.orderings:
            self.children[landmarks[parent]] |= 1 << landmarks[child]
            parents.setdefault(landmarks[child], []).append(landmarks[parent])
        self.orderings = len(found.orderings)
        # per landmark: the landmarks ordered (transitively) before it
        self.ancestors = [0] * n
        for i in range(n):
            mask, todo = 0, list(parents.get(i, ()))
            while todo:
                j = todo.pop()
                if not mask & (1 << j):
                    mask |= 1 << j
                    todo.extend(parents.get(j, ()))
            self.ancestors[i] = mask
        # a landmark no relaxed plan from the initial state reaches: a state
        # that still needs it is a dead end (all are when the goal is one)
        self.dead = sum(1 << landmarks[node] for node in found.unreachable if node in landmarks)
        self.unsolvable = frozenset({r.goal}) in found.unreachable
        self.reached: dict = {task.init: self.true_in(task.init)}
        # without landmarks the count is 0 everywhere (dead ends aside)
        self.informative = bool(self.landmarks) or self.unsolvable

    def true_in(self, state) -> int:
        bit = self.bit
        mask = 0
        for f in state:
            mask |= bit[f]
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


class _Backchain:
    """Landmarks (node -> index; a node is a frozenset of facts, one of which
    every plan makes true), greedy-necessary orderings (parent node, child
    node), and the nodes (auxiliary ones too) unreachable in the relaxation."""

    def __init__(self, r: RelaxedTask, achievers, real, predicate, init):
        self.landmarks: dict[frozenset[int], int] = {}
        self.orderings: set[tuple[frozenset[int], frozenset[int]]] = set()
        self.unreachable: set[frozenset[int]] = set()
        goal = frozenset({r.goal})
        targets: dict[frozenset[int], frozenset] = {goal: frozenset()}
        queue, seen = [goal], {goal}
        in_disjunction: set[int] = set()  # facts of a disjunctive landmark: no overlaps
        while queue:
            node = queue.pop(0)
            if not node.isdisjoint(init):
                continue
            reached = _reachable_without(r, node, init)
            first = [a for a in {a for f in node for a in achievers[f]}
                     if all(reached[p] for p in r.pre[a])]
            if not first:
                self.unreachable.add(node)
                continue
            shared = set(r.pre[first[0]]).intersection(*(r.pre[a] for a in first[1:]))
            found = [frozenset({p}) for p in sorted(shared)]
            found += _disjunctive(r, first, shared, real, predicate, init)
            # orderings go to the nearest real landmarks after `node`
            after = frozenset({node}) if _is_real(node, real) else targets[node]
            for new in found:
                if len(new) > 1 and new not in self.landmarks and any(
                        frozenset({f}) in self.landmarks or f in in_disjunction for f in new):
                    continue
                if len(new) > 1:
                    in_disjunction.update(new)
                if _is_real(new, real):
                    self.orderings.update((new, child) for child in after)
                    self.landmarks.setdefault(new, len(self.landmarks))
                else:
                    targets[new] = targets.get(new, frozenset()) | after
                if new not in seen:
                    seen.add(new)
                    queue.append(new)
        # a disjunction holding a fact that is a landmark alone says nothing more
        singles = {f for node in self.landmarks if len(node) == 1 for f in node}
        kept = [node for node in self.landmarks if len(node) == 1 or node.isdisjoint(singles)]
        self.landmarks = {node: i for i, node in enumerate(kept)}
        self.orderings = {(a, b) for a, b in self.orderings
                          if a in self.landmarks and b in self.landmarks}


def _is_real(node: frozenset[int], real) -> bool:
    return all(real[f] for f in node)


def _disjunctive(r: RelaxedTask, first, shared, real, predicate, init) -> list[frozenset[int]]:
    """Per predicate that every first achiever needs (outside `shared`), the
    facts of it they need: one of them is a landmark. Kept small (2 to 4
    facts, none true initially), as RHW does."""
    by_predicate: dict[str, set[int]] | None = None
    for a in first:
        mine: dict[str, set[int]] = {}
        for p in r.pre[a]:
            if p not in shared and real[p]:
                mine.setdefault(predicate[p], set()).add(p)
        if by_predicate is None:
            by_predicate = mine
        else:
            by_predicate = {k: v | mine[k] for k, v in by_predicate.items() if k in mine}
        if not by_predicate:
            return []
    return [frozenset(facts) for _, facts in sorted(by_predicate.items())
            if 2 <= len(facts) <= 4 and facts.isdisjoint(init)]


def _reachable_without(r: RelaxedTask, banned: frozenset[int], init) -> bytearray:
    """Facts relaxed-reachable from `init` by actions that add no fact of `banned`."""
    reached = bytearray(r.n_facts)
    unsat = r.pre_count[:]
    stack = []
    for f in init:
        reached[f] = 1
        stack.append(f)
    for a in r.no_pre:
        if banned.isdisjoint(r.add[a]):
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
                if not banned.isdisjoint(add):
                    continue
                for q in add:
                    if not reached[q]:
                        reached[q] = 1
                        stack.append(q)
    return reached
