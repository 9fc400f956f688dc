"""The ground task as 0/1 variables: the lesson's LGP view (§3).

Fact variables y[k][f] (state after the event at waypoint k; y[0] is the
initial state) and action variables d[k][i] per ground operator i at
waypoint k = 1..T, one-hot with a no-op. Preconditions are y >= d; effects
and frame axioms link y[k-1], d[k] and y[k]:

    y[k][f] >= sum of d[k][i] over operators adding f
    y[k][f] <= 1 - sum of d[k][i] over operators deleting (and not adding) f
    y[k][f] - y[k-1][f] <= sum of d[k][i] adding f        (nothing else makes f true)
    y[k-1][f] - y[k][f] <= sum of d[k][i] deleting f      (nothing else makes f false)

With one operator a step these are exactly STRIPS progression. Condition trees
(disjunctive preconditions and goals) get one auxiliary 0/1 variable per
inner node. Axioms and conditional effects are refused.
"""

from __future__ import annotations

from dataclasses import dataclass

from pyscipopt import quicksum

from tampcli.errors import UnsupportedFeatureError
from tampcli.task.task import Condition, Task


@dataclass(frozen=True)
class SymbolicVars:
    y: tuple[tuple[object, ...], ...]  # y[k][f], k = 0..T
    d: tuple[tuple[object, ...], ...]  # d[k][i], k = 0..T (d[0] is empty: nothing at the start)
    noop: tuple[object, ...]  # noop[k], k = 0..T (noop[0] is None)


def check_supported(task: Task, path: str | None) -> None:
    if task.axioms:
        raise UnsupportedFeatureError("the MINLP does not encode derived predicates (axioms)",
                                      path)
    if task.has_conditional_effects:
        raise UnsupportedFeatureError("the MINLP does not encode conditional effects", path)


def encode_task(model, task: Task, steps: int, disabled: frozenset[int]) -> SymbolicVars:
    """Fact and action variables for T = `steps`; operators in `disabled` are fixed to 0."""
    n_facts = len(task.facts)
    y = [tuple(model.addVar(f"y_{f}_0", vtype="B", lb=float(f in task.init),
                            ub=float(f in task.init)) for f in range(n_facts))]
    d: list[tuple] = [()]
    noop: list = [None]
    adders = [[] for _ in range(n_facts)]
    deleters = [[] for _ in range(n_facts)]
    for i, op in enumerate(task.operators):
        for f in op.add:
            adders[f].append(i)
        for f in op.delete - op.add:
            deleters[f].append(i)
    for k in range(1, steps + 1):
        dk = tuple(model.addVar(f"d_{i}_{k}", vtype="B", ub=0.0 if i in disabled else 1.0)
                   for i in range(len(task.operators)))
        nk = model.addVar(f"noop_{k}", vtype="B")
        model.addCons(quicksum(dk) + nk == 1, name=f"onehot_{k}")
        yk = tuple(model.addVar(f"y_{f}_{k}", vtype="B") for f in range(n_facts))
        for i, op in enumerate(task.operators):
            _require(model, op.pre, y[k - 1], dk[i], f"pre_{i}_{k}")
        for f in range(n_facts):
            add = quicksum(dk[i] for i in adders[f])
            delete = quicksum(dk[i] for i in deleters[f])
            if adders[f]:
                model.addCons(yk[f] >= add, name=f"add_{f}_{k}")
            if deleters[f]:
                model.addCons(yk[f] <= 1 - delete, name=f"del_{f}_{k}")
            model.addCons(yk[f] - y[k - 1][f] <= add, name=f"frame_up_{f}_{k}")
            model.addCons(y[k - 1][f] - yk[f] <= delete, name=f"frame_down_{f}_{k}")
        y.append(yk)
        d.append(dk)
        noop.append(nk)
    _require(model, task.goal, y[steps], 1.0, "goal")
    return SymbolicVars(tuple(y), tuple(d), tuple(noop))


def _require(model, cond: Condition, y, switch, name: str) -> None:
    """cond holds on state y whenever `switch` (a 0/1 variable or 1.0) is 1."""
    for f in cond.pos:
        model.addCons(y[f] >= switch, name=f"{name}_pos_{f}")
    for f in cond.neg:
        model.addCons(1 - y[f] >= switch, name=f"{name}_neg_{f}")
    for j, tree in enumerate(cond.extra):
        model.addCons(_truth(model, tree, y, f"{name}_t{j}") >= switch, name=f"{name}_x{j}")


def _truth(model, tree, y, name: str):
    """A 0/1 expression that is 1 only if the condition tree holds on y."""
    if isinstance(tree, int):
        return y[tree] if tree >= 0 else 1 - y[~tree]
    tag, parts = tree
    z = model.addVar(name, vtype="B")
    values = [_truth(model, part, y, f"{name}_{j}") for j, part in enumerate(parts)]
    if tag == "and":
        for j, v in enumerate(values):
            model.addCons(z <= v, name=f"{name}_and{j}")
    else:
        model.addCons(z <= quicksum(values), name=f"{name}_or")
    return z
