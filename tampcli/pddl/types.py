"""The type hierarchy of a domain: which types an object of a given type belongs to."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from tampcli.pddl import ast

OBJECT = "object"


@dataclass(frozen=True)
class TypeHierarchy:
    """`ancestors[t]`: t itself, its parents, theirs... up to `object`.

    `(:types a - (either b c))` gives `a` two parents. A cycle is cut where
    it closes (check.py reports it).
    """

    ancestors: dict[str, frozenset[str]]
    cyclic: tuple[str, ...] = ()  # types that are their own ancestors

    @classmethod
    def of(cls, domain: ast.Domain) -> TypeHierarchy:
        parents: dict[str, set[str]] = {OBJECT: set()}
        for typed in domain.types:
            parents.setdefault(typed.name, set()).update(
                t for t in typed.types if t != typed.name)
        for typed in domain.types:
            for parent in typed.types:
                parents.setdefault(parent, {OBJECT} if parent != OBJECT else set())
        ancestors: dict[str, frozenset[str]] = {}
        cyclic = []
        for name in parents:
            seen, todo = set(), list(parents[name])
            while todo:
                t = todo.pop()
                if t not in seen:
                    seen.add(t)
                    todo.extend(parents.get(t, ()))
            if name in seen:
                cyclic.append(name)
            ancestors[name] = frozenset(seen | {name, OBJECT})
        return cls(ancestors, tuple(cyclic))

    def __contains__(self, name: str) -> bool:
        return name in self.ancestors

    def is_subtype(self, sub: str, sup: str) -> bool:
        return sup in self.ancestors.get(sub, (sub, OBJECT))

    def fits(self, types: Iterable[str], allowed: Iterable[str]) -> bool:
        """Whether a value of one of `types` is always one of `allowed` (objects, constants)."""
        allowed = tuple(allowed)
        return all(any(self.is_subtype(t, a) for a in allowed) for t in types)

    def may_fit(self, types: Iterable[str], allowed: Iterable[str]) -> bool:
        """Whether some object could be both of one of `types` and one of `allowed`.

        Used for variables: a parameter `?x - vehicle` may be passed where a
        `truck` is expected (the precondition then holds only for trucks); a
        `?x - place` where a `truck` is expected can never hold.
        """
        allowed = tuple(allowed)
        for t in types:
            for a in allowed:
                if self.is_subtype(t, a) or self.is_subtype(a, t):
                    return True
                if any(a in anc and t in anc for anc in self.ancestors.values()):
                    return True
        return False
