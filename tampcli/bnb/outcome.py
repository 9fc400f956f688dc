"""How a branch and bound ended, in words: the `stop` label and, without a
solution, the reason."""

from __future__ import annotations

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


def explain(stop_reason, tried, failures, deepest_feasible, options) -> str:
    """Why there is no solution: the limit, the deepest feasible keyframes, the
    first failures."""
    if tried == 0:
        return "no skeleton: the task is symbolically unsolvable"
    parts = []
    limits = {"time": f"time limit ({options.time_limit:g} s) reached",
              "skeletons": f"skeleton limit ({options.max_skeletons}) reached",
              "exhausted": "every skeleton was tried"}
    parts.append(f"{limits.get(stop_reason, stop_reason)} after {tried} skeleton(s), "
                 "none geometrically feasible")
    if deepest_feasible:
        parts.append(f"deepest feasible keyframe sequence: {' '.join(deepest_feasible)}")
    for rank, plan, _stage, why in failures[:3]:
        parts.append(f"#{rank} {' '.join(plan)}: {why}")
    if len(failures) > 3:
        parts.append(f"... and {len(failures) - 3} more")
    return "; ".join(parts)
