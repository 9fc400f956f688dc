"""Keyframe results of branch and bound by action-name prefix: a memo, the warm
start of a longer skeleton, and the infeasible prefixes that prune others."""

from __future__ import annotations

from typing import Any


class PrefixTree:
    """Results of keyframe problems by action-name prefix (memo + warm starts)."""

    def __init__(self):
        self._results: dict[tuple[str, ...], Any] = {}
        self.infeasible: set[tuple[str, ...]] = set()

    def get(self, prefix: tuple[str, ...]):
        return self._results.get(prefix)

    def put(self, prefix: tuple[str, ...], result) -> None:
        self._results[prefix] = result
        if result.status != "solved":
            self.infeasible.add(prefix)

    def blocked(self, names: tuple[str, ...]) -> tuple[str, ...] | None:
        for i in range(1, len(names) + 1):
            if names[:i] in self.infeasible:
                return names[:i]
        return None

    def warm_for(self, names: tuple[str, ...]):
        """The solved result of the longest evaluated proper prefix, if any."""
        for i in range(len(names), 0, -1):
            result = self._results.get(names[:i])
            if result is not None and result.status == "solved":
                return result
        return None


def shortest_failing_prefix(ops, names, tree: PrefixTree, run_stage, is_geometric):
    """Shortest prefix (ending at a geometric action) whose keyframe problem fails."""
    for i in range(1, len(ops)):
        if not is_geometric(ops[i - 1]):
            continue
        prefix = names[:i]
        known = tree.get(prefix)
        if known is None:
            known = run_stage(ops[:i], "keyframes", tree.warm_for(prefix[:-1]))
            tree.put(prefix, known)
        if known.status == "infeasible":
            return prefix
    return names
