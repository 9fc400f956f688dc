"""A skeleton source whose own time is counted apart from the NLPs'."""

from __future__ import annotations

import time


class TimedSource:
    """Wraps a skeleton source (search.learned.LearningSource): the time it spends
    producing skeletons and its bound goes to `timers.add("search", seconds)`; its
    learning and scope pass through."""

    def __init__(self, topk, timers):
        self.topk, self.timers = topk, timers

    @property
    def scope(self) -> str:
        return self.topk.scope

    @property
    def proofs(self) -> int:
        return getattr(self.topk, "proofs", 0)

    def proof_names(self) -> tuple[str, ...]:
        named = getattr(self.topk, "proof_names", None)
        return named() if named is not None else ()

    def forbid_prefix(self, names):
        self.topk.forbid_prefix(names)

    def solved(self, names):
        self.topk.solved(names)

    def waiting_on_results(self) -> bool:
        return self._timed(self.topk.waiting_on_results)

    def lower_bound(self) -> float:
        return self._timed(self.topk.lower_bound)

    def _timed(self, call):
        """`call()`, its time counted as the search's."""
        start = time.perf_counter()
        try:
            return call()
        finally:
            self.timers.add("search", time.perf_counter() - start)

    def __iter__(self):
        iterator = iter(self.topk)
        while True:
            start = time.perf_counter()
            try:
                plan = next(iterator)
            except StopIteration:
                return
            finally:
                self.timers.add("search", time.perf_counter() - start)
            yield plan
