"""Prefix nodes and their bounds (the seed's §5, Problem 4).

A node is a prefix of a skeleton ending at a geometric action; its bound is
the value of the prefix's trajectory problem with the rest relaxed: every
completion of the prefix costs at least that much (what is added costs
>= 0). `relax(ops)` gives it as a value with a kind ("proved" when the
relaxation was solved to global optimality with a certificate, else
"heuristic"), or None when there is no relaxation (then only the symbolic
bound remains). A node is expanded, shortest prefix first, only while its
bound is below the incumbent; the first that is not prunes every skeleton
that starts with it.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, Protocol


class RelaxedValue(Protocol):
    value: float  # a lower bound of the trajectory cost (inf: no trajectory at all)
    kind: str  # "proved" | "heuristic"  (optional: `why`, what makes it infeasible)


Relax = Callable[[Sequence[Any]], RelaxedValue | None]


@dataclass(frozen=True)
class NodeBound:
    prefix: tuple[str, ...]
    value: float  # trajectory cost of every completion is >= value (inf: infeasible)
    proved: bool
    why: str | None = None  # what makes the relaxation infeasible, when said


@dataclass(frozen=True)
class Prune:
    """The shortest node that excludes a skeleton, and why, in words."""

    node: NodeBound
    reason: str

    @property
    def infeasible(self) -> bool:
        return math.isinf(self.node.value)

    @property
    def worst_constraint(self) -> str | None:
        """What makes the relaxation infeasible, as a failed stage says it (for `learn`)."""
        return self.node.why if self.infeasible else None


class PrefixBounds:
    """Bounds of prefix nodes, each relaxation solved once (skeletons share prefixes)."""

    def __init__(self, relax: Relax, is_geometric: Callable[[Any], bool]):
        self.relax, self.is_geometric = relax, is_geometric
        self.memo: dict[tuple[str, ...], NodeBound | None] = {}

    def node(self, ops: Sequence[Any], names: tuple[str, ...]) -> NodeBound | None:
        if names not in self.memo:
            out = self.relax(ops)
            self.memo[names] = None if out is None else NodeBound(
                names, float(out.value), out.kind == "proved", getattr(out, "why", None))
        return self.memo[names]

    def judge(self, ops: Sequence[Any], names: tuple[str, ...], symbolic: float,
              undrawn: float, weight: float, incumbent: float | None,
              tie: float = 1e-12) -> tuple[NodeBound | None, Prune | None]:
        """(the whole skeleton's node, or the deepest one evaluated; the shortest
        node that prunes the skeleton, or None).

        A proper prefix is judged with the least symbolic cost of a completion
        still to come: min(this skeleton's, `undrawn`, a bound on every skeleton
        not drawn yet); the whole skeleton with its own.
        """
        last = None
        ends = [i for i in range(1, len(ops)) if self.is_geometric(ops[i - 1])]
        for i in [*ends, len(ops)]:
            node = self.node(ops[:i], names[:i])
            if node is None:
                return last, None
            last = node
            whole = i == len(ops)
            least = symbolic if whole else min(symbolic, undrawn)
            where = "the skeleton" if whole else f"the prefix {' '.join(names[:i])}"
            label = "proved" if node.proved else "heuristic"
            if math.isinf(node.value):
                why = f": {node.why}" if node.why else ""
                return node, Prune(node, f"the relaxed trajectory problem of {where} is "
                                         f"infeasible ({label}){why}")
            total = node.value + weight * least
            if incumbent is not None and total >= incumbent - tie:
                return node, Prune(node, f"relaxed bound of {where} {total:.4g} >= incumbent "
                                         f"{incumbent:.4g} ({label})")
        return last, None
