"""How a branch and bound ended, in words: the `stop` label and, without a
solution, the reason."""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass
from typing import Any

TIE = 1e-12  # objectives this close count as equal when a bound is compared

LIMITS = {"time": "time limit", "skeletons": "skeleton limit", "first": "first solution"}


def heuristic_prunes(objective: float | None, unproved: list[float]) -> int:
    """Skeletons excluded without proof whose proved bound is below the objective:
    each may hide a better solution."""
    if objective is None:
        return len(unproved)
    return sum(b < objective - TIE for b in unproved)


def stop_label(stop: str, objective: float | None, proved_lb: float | None,
               unproved: list[float]) -> str:
    """"optimal (proved)" when the proved bound meets the objective; "best of the
    evaluated skeletons (N heuristic prunes)" when the search ended by its own
    bound or ran out of skeletons with an answer; else the limit that stopped it."""
    if stop in LIMITS:
        return LIMITS[stop]
    if objective is None:
        return "every skeleton tried"
    if proved_lb is not None and proved_lb >= objective - TIE:
        return "optimal (proved)"
    return f"best of the evaluated skeletons ({heuristic_prunes(objective, unproved)} " \
           "heuristic prunes)"


@dataclass(frozen=True)
class Failure:
    """A skeleton whose stage failed: its record's words, and what `Diagnose`
    (values.py) needs to say more of it when the search ends without a solution."""

    rank: int
    plan: tuple[str, ...]
    why: str
    ops: tuple[Any, ...] = ()
    result: Any = None  # the failed stage's result


@dataclass(frozen=True)
class Ending:
    """How a search without a solution ended, for `explain`."""

    stop: str  # "time" | "skeletons" | "exhausted" | ...
    tried: int  # skeletons drawn
    proved: bool  # every failure proved (the status is then "unsolvable")
    # Prefixes forbidden after a local NLP failure: heuristic exclusions of every
    # skeleton starting with one.
    learned_prefixes: tuple[tuple[str, ...], ...] = ()
    scope: str | None = None  # which skeletons the source yields, in words
    proofs: int = 0  # geometric proofs compiled into the task before any skeleton
    proof_names: tuple[str, ...] = ()  # those proofs in words (with their causes)


SHOWN = 3  # failures (and learned prefixes) named in the reason


def explain(ending: Ending, failures: list[Failure], deepest_feasible, options,
            diagnose=None) -> str:
    """Why there is no solution: how the search ended (a limit, or no skeleton left,
    and whether learned prefixes, a heuristic, excluded the rest), the deepest
    feasible keyframes, the first failures with what `diagnose` finds violated."""
    if ending.tried == 0 and ending.proofs:
        # Not the symbols' doing (blind28 p06: `plan` found the plan in 1 ms; a false
        # reach proof had ruled out its first pick).
        named = "; ".join(ending.proof_names[:SHOWN]) + (
            f"; and {len(ending.proof_names) - SHOWN} more" if len(ending.proof_names) > SHOWN
            else "")
        return (f"no skeleton: every plan breaks one of the {ending.proofs} geometric "
                "proof(s) made before any skeleton"
                + (f": {named}" if named else "")
                + " (`stats.proved_first_moves` lists them)")
    if ending.tried == 0:
        return "no skeleton: the task is symbolically unsolvable"
    parts = [_how(ending, options)]
    if deepest_feasible:
        parts.append(f"deepest feasible keyframe sequence: {' '.join(deepest_feasible)}")
    for failure in failures[:SHOWN]:
        detail = None if diagnose is None or failure.result is None else \
            diagnose(failure.ops, failure.result)
        parts.append(f"#{failure.rank} {' '.join(failure.plan)}: {failure.why}"
                     + (f" [violated at the NLP's best point, by action: {detail}]"
                        if detail else ""))
    if len(failures) > SHOWN:
        parts.append(f"... and {len(failures) - SHOWN} more")
        commonest = _commonest(failures)
        if commonest is not None:
            parts.append(commonest)
    return "; ".join(parts)


_FIGURES = re.compile(r"(?<![\w-])\d+(\.\d+)?")  # 0.8 in "by 0.8 cm", not 1 in "b1"


def _commonest(failures: list[Failure]) -> str | None:
    """The failure most skeletons ended on, its figures aside, where it is more than one
    skeleton's: the one place the rest of the list points at (blind20 p01: 318 of 320
    skeletons failed placing the pen in its case, the reason named three)."""
    def key(f: Failure) -> str:
        return _FIGURES.sub("#", f.why)

    counts = Counter(key(f) for f in failures)
    common, n = counts.most_common(1)[0]
    if n < 2:
        return None
    example = next(f.why for f in failures if key(f) == common)
    return f"the commonest failure, {n} of {len(failures)} skeletons: {example}"


def _how(ending: Ending, options) -> str:
    none = f"after {ending.tried} skeleton(s), none geometrically feasible"
    if ending.stop == "time":
        return f"time limit ({options.time_limit:g} s) reached {none}"
    if ending.stop == "skeletons":
        return f"skeleton limit ({options.skeleton_limit(False):g}) reached {none}"
    if ending.stop != "exhausted":
        return f"{ending.stop} {none}"
    prefixes = ending.learned_prefixes
    if prefixes:
        named = ", ".join(" ".join(p) for p in prefixes[:SHOWN])
        more = f" and {len(prefixes) - SHOWN} more" if len(prefixes) > SHOWN else ""
        return (f"no skeleton left {none}: every other skeleton starts with one of "
                f"{len(prefixes)} prefix(es) forbidden after a local NLP failure ({named}{more}), "
                "a heuristic exclusion, not a proof that no skeleton is feasible")
    scope = f"; {ending.scope}" if ending.scope else ""
    proof = "" if ending.proved else \
        " (not a proof: a local NLP that finds no feasible point may have missed one)"
    return f"every skeleton was tried ({ending.tried}{scope}), none geometrically feasible{proof}"
