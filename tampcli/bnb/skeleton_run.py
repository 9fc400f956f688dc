"""One skeleton's stages, as a worker of the parallel search runs them
(bnb/parallel.py): the job it is given, the run it gives back, and the
serial search's stages in between (StageSteps._run_stages, a prefix's reach
first: prefix_reach.py). Picklable both ways: a worker may be another process.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from tampcli.bnb import prefix_reach
from tampcli.bnb.prefix_tree import PrefixTree, shortest_failing_prefix
from tampcli.bnb.stage_steps import BOUNDING, STAGES, call_stage
from tampcli.bnb.values import Evaluate


@dataclass(frozen=True)
class SkeletonJob:
    """One skeleton's NLPs, as a worker needs them (picklable)."""

    rank: int
    names: tuple[str, ...]
    symbolic: float
    known: tuple[tuple[tuple[str, ...], Any], ...]  # keyframe results of its prefixes
    incumbent: float | None  # objective when sent: a keyframe bound above it stops there
    weight: float
    anytime: bool
    prefix_pruning: bool
    per_action: float | None = None  # the incumbent's cost per geometric action (prefix_reach)


@dataclass(frozen=True)
class SkeletonRun:
    """What a worker found: each stage run in order, and the keyframe results of
    the prefixes it solved (its own included)."""

    stages: tuple[tuple[str, Any], ...]
    keyframes: tuple[tuple[tuple[str, ...], Any], ...]
    nlp_solves: int
    iterations: int
    seconds: float


def run_skeleton(job: SkeletonJob, ops, evaluate: Evaluate,
                 is_geometric: Callable[[Any], bool],
                 incumbent: Callable[[], float] = lambda: math.inf,
                 per_action: Callable[[], float | None] = lambda: None) -> SkeletonRun:
    """The serial search's stages for one skeleton (run in a worker).

    `incumbent()` is the best objective of the lower ranks known now
    (`Workers.found`), maybe lower than the job's: it saves the later stages of a
    skeleton that cannot win. The books come out the same whatever it says, as
    its stages are applied in order when the run is taken, against an incumbent
    no higher (_ParallelSearch._take: the rare answer the books then reject is
    the exception, recorded as such).
    """
    started = time.perf_counter()
    tree, stages, counts = PrefixTree(), [], [0, 0]
    for prefix, result in job.known:
        tree.put(prefix, result)

    def stage(prefix_ops, name, warm, cutoff=None):
        result = call_stage(evaluate, prefix_ops, name, warm, cutoff)
        solves = getattr(result, "nlp_solves", None)  # as StageSteps._stage counts
        counts[0] += 1 if solves is None else solves
        counts[1] += getattr(result, "iterations", 0) or 0
        return result

    warm = tree.warm_for(job.names)
    early = _prefix_reach(job, ops, is_geometric, incumbent, per_action, stage, tree)
    for name in STAGES if early is None else ():
        best = min(math.inf if job.incumbent is None else job.incumbent, incumbent())
        cutoff = best - job.weight * job.symbolic \
            if name == "path" and math.isfinite(best) and not job.anytime else None
        result = stage(ops, name, warm, cutoff)
        stages.append((name, result))
        if name == "keyframes":
            tree.put(job.names, result)
        if result.status != "solved":
            if name == "reach":  # as the serial search: the relaxation decides nothing
                continue
            if name == "keyframes" and job.prefix_pruning and result.status == "infeasible":
                shortest_failing_prefix(ops, job.names, tree, stage, is_geometric)
            break
        warm = result
        best = min(math.inf if job.incumbent is None else job.incumbent, incumbent())
        if name in BOUNDING and result.cost is not None and not job.anytime \
                and result.cost + job.weight * job.symbolic >= best:
            break
    if early is not None:
        stages.append(("reach", early))
    known = {prefix for prefix, _ in job.known}
    keyframes = tuple((job.names[:i], tree.get(job.names[:i]))
                      for i in range(1, len(job.names) + 1)
                      if job.names[:i] not in known and tree.get(job.names[:i]) is not None)
    return SkeletonRun(tuple(stages), keyframes, counts[0], counts[1],
                       time.perf_counter() - started)


def _prefix_reach(job: SkeletonJob, ops, is_geometric, incumbent, per_action, stage, tree):
    """The reach result of a short prefix that prunes the skeleton, or None
    (bnb/prefix_reach.py; the serial search's StageSteps._prefix_reach_prunes)."""
    if job.anytime:
        return None
    best = min(math.inf if job.incumbent is None else job.incumbent, incumbent())
    each = job.per_action if job.per_action is not None else per_action()
    return prefix_reach.pruning_reach(
        ops, is_geometric, best, job.weight * job.symbolic, each,
        lambda i: stage(ops[:i], "reach", tree.warm_for(job.names[:i])))


def answer(job: SkeletonJob, run: SkeletonRun, ops, is_geometric) -> tuple[float, float | None] | None:
    """The path `run` found, as the workers are told of it (Workers.found): its
    objective and trajectory cost per geometric action; None without one."""
    for stage, result in run.stages:
        if stage == "path" and result.status == "solved" and result.cost is not None:
            return (result.cost + job.weight * job.symbolic,
                    prefix_reach.per_action(result.cost, ops, is_geometric))
    return None
