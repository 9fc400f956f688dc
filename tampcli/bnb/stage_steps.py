"""One skeleton's stages in branch and bound: run in turn, each result applied to its
trial (a failure, a bound that prunes, the path it found). A mixin of
bnb._Search, whose state (incumbent, tree, stats, records) it reads and writes."""

from __future__ import annotations

from tampcli.bnb import prefix_reach
from tampcli.bnb.prefix_tree import shortest_failing_prefix
from tampcli.bnb.values import Event

STAGES = ("final", "reach", "keyframes", "path")
# Stages whose cost bounds the skeleton's (heuristically: local optima): "reach" is the
# keyframe NLP with collisions dropped, a relaxation a tenth of the keyframe NLP's time.
BOUNDING = ("reach", "keyframes")


def call_stage(evaluate, ops, stage: str, warm, cutoff: float | None = None):
    """`evaluate` (values.Evaluate) of one stage: `cutoff` is passed only when there is
    one, so an evaluator of three arguments serves a search with no incumbent."""
    if cutoff is None:
        return evaluate(ops, stage, warm)
    return evaluate(ops, stage, warm, cutoff=cutoff)


class StageSteps:
    def _stage(self, ops, stage: str, warm, cutoff: float | None = None):
        t0 = self.clock()
        result = call_stage(self.evaluate, ops, stage, warm, cutoff)
        # A stage refused before any NLP (a proof) solved none (blind35 DOC_GAPS 6: such
        # a refusal counted one); an evaluator that does not say counts one.
        solves = getattr(result, "nlp_solves", None)
        self.stats["nlp_solves"] += 1 if solves is None else solves
        self.stats["nlp_iterations"] += getattr(result, "iterations", 0) or 0
        self.stats["optimize_seconds"] += self.clock() - t0
        return result

    def _run_stages(self, trial) -> None:
        """Final placements, the relaxed and the real keyframes, full path: stop at the
        first that fails or whose bound cannot beat the incumbent."""
        warm = self.tree.warm_for(trial.names)
        if self._prefix_reach_prunes(trial):
            return
        for stage in STAGES:
            trial.reached = stage
            self.emit(Event("stage", trial.rank, trial.names, trial.symbolic, stage=stage,
                            seconds=self.elapsed()))
            result = self._stage(trial.ops, stage, warm, self._cutoff(trial, stage))
            if stage == "keyframes":
                self.tree.put(trial.names, result)
            if not self._apply_stage(trial, stage, result):
                return
            if result.status == "solved":
                warm = result

    def _prefix_reach_prunes(self, trial) -> bool:
        """Pruned by the reach bound of a short prefix (bnb/prefix_reach.py)."""
        if self.incumbent is None or self.options.anytime:
            return False

        def solve(i):  # each prefix's reach once (skeletons share prefixes)
            prefix = trial.names[:i]
            if prefix not in self.prefix_reaches:
                self.prefix_reaches[prefix] = self._stage(trial.ops[:i], "reach",
                                                          self.tree.warm_for(prefix))
            return self.prefix_reaches[prefix]

        result = prefix_reach.pruning_reach(trial.ops, self.is_geometric,
                                            self.incumbent.objective,
                                            self.w * trial.symbolic, self._each(), solve)
        if result is None:
            return False
        trial.reached = "reach"
        return not self._apply_stage(trial, "reach", result)

    def _each(self) -> float | None:
        """The incumbent's trajectory cost per geometric action (prefix_reach.py)."""
        if self.incumbent is None:
            return None
        return prefix_reach.per_action(getattr(self.incumbent.result, "cost", None),
                                       self.incumbent.plan, self.is_geometric)

    def _cutoff(self, trial, stage: str) -> float | None:
        """The trajectory cost at which `trial` cannot beat the incumbent (path stage)."""
        if stage != "path" or self.incumbent is None or self.options.anytime:
            return None
        return self.incumbent.objective - self.w * trial.symbolic

    def _apply_stage(self, trial, stage: str, result) -> bool:
        """One stage's result into the trial; False when the trial ends there."""
        if result.status == "bounded":
            trial.outcome = "pruned"
            trial.heuristic_bound = result.cost + self.w * trial.symbolic
            # (In a parallel search the cutoff may come from a better skeleton of a later
            # rank, not yet in the books: it beats this one all the same.)
            trial.reason = (f"{result.worst_constraint}: objective {trial.heuristic_bound:.4g}"
                            " >= the incumbent's (heuristic: keyframes fixed)")
            self._unproved(trial)
            return False
        if result.status != "solved":
            if stage == "reach":  # a relaxation's local failure proves nothing
                return True
            self._stage_failed(trial, stage, result)
            return False
        trial.kkt = getattr(result, "kkt", None) or trial.kkt
        # A reach of fewer actions than the skeleton's is a prefix's (prefix_reach.py).
        names = getattr(result, "names", ())
        prefix = len(names) if 0 < len(names) < len(trial.names) else None
        if stage in BOUNDING and result.cost is not None \
                and self._keyframe_bound_prunes(trial, result.cost, stage, prefix):
            return False
        if stage == "path":
            trial.path_result, trial.nlp_cost = result, result.cost
        return True

    def _stage_failed(self, trial, stage: str, result) -> None:
        trial.outcome, trial.failed, trial.failed_stage = "infeasible", result, stage
        self.learn(result)
        trial.reason = f"{stage} stage {result.status}: {result.worst_constraint or 'no detail'}"
        if not getattr(result, "proved", False) or result.status == "limit":
            self.all_proved_infeasible = False
            self._unproved(trial)
        failed = getattr(result, "failed_actions", None)
        if stage == "path" and self.options.prefix_pruning and result.status == "infeasible" \
                and failed is not None and hasattr(self.skeletons, "forbid_prefix"):
            # A motion that found no path, with the sampler and every grip tried, fails
            # again after the same actions: the skeletons sharing them are not worth
            # their path stage (robust-planar p02: a blocker boxed in by two others,
            # each order taking it first ~25 s), those that go on after its last action
            # too (blind19 p04: the carry through a blocked door, then more, 30 s).
            # Heuristic, as the keyframe prefixes are: this skeleton's bound stays
            # among the unproved.
            prefix = trial.names[:failed]
            self.skeletons.forbid_prefix(prefix)
            self.stats["prefixes_forbidden"] += 1
            self.learned_prefixes.append(prefix)
            trial.reason += f" (prefix {' '.join(prefix)} failed)"
        if stage != "path" and getattr(result, "proved", False) and failed is not None \
                and result.status == "infeasible" and hasattr(self.skeletons, "forbid_prefix"):
            # A proof made while lowering (`(pick plate home): plate is under another
            # object`) comes from the actions up to the one it names: every skeleton
            # starting with them fails it too (blind37 p02: 35 such refusals one by one
            # before the answer, at #38). A proof, not a heuristic: the bound stays.
            prefix = trial.names[:failed]
            self.skeletons.forbid_prefix(prefix)
            self.stats["prefixes_forbidden"] += 1
            trial.reason += f" (prefix {' '.join(prefix)} is proved infeasible)"
            return
        if stage == "keyframes" and self.options.prefix_pruning \
                and result.status == "infeasible":
            prefix = shortest_failing_prefix(trial.ops, trial.names, self.tree, self._stage,
                                              self.is_geometric)
            if prefix is not None and prefix != trial.names \
                    and hasattr(self.skeletons, "forbid_prefix"):
                self.skeletons.forbid_prefix(prefix)
                self.stats["prefixes_forbidden"] += 1
                self.learned_prefixes.append(prefix)
                trial.reason += f" (prefix {' '.join(prefix)} is infeasible)"

    def _keyframe_bound_prunes(self, trial, keyframe_cost: float, stage: str,
                               prefix: int | None = None) -> bool:
        trial.heuristic_bound = keyframe_cost + self.w * trial.symbolic
        if (self.incumbent is not None and not self.options.anytime
                and trial.heuristic_bound >= self.incumbent.objective):
            trial.outcome = "pruned"
            what = "keyframe" if stage == "keyframes" else f"{stage} (keyframes, no collisions)"
            if prefix is not None:
                what += f" of its first {prefix} actions"
            trial.reason = (f"{what} bound {trial.heuristic_bound:.4g} >= incumbent "
                            f"{self.incumbent.objective:.4g} (heuristic)")
            self._unproved(trial)
            return True
        if stage == "keyframes" and len(trial.names) > len(self.deepest_feasible):
            self.deepest_feasible = trial.names
        return False

