"""The whole TAMP pipeline in one place: each stage run in order, timed by name.

    parse -> ground -> scene -> (top-k skeletons x trajectory NLPs: branch and bound) -> Solution

Heavy modules (numpy, pybullet, scipy) are imported only when a scene exists.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from contextlib import contextmanager
from dataclasses import dataclass

from tampcli.bnb import BnBOptions, Event, branch_and_bound
from tampcli.pddl import parser
from tampcli.solution import Phase, Solution


@dataclass(frozen=True)
class SolveOptions:
    """Options of `tampcli solve`.

    max_skeletons: skeletons drawn at most (-k).
    time_limit: seconds for the whole solve.
    symbolic_weight: w in objective = trajectory cost + w * symbolic cost.
    waypoints: waypoints per motion phase.
    anytime: keep improving until a limit.
    seed: random seed (IK restarts, tie-breaking): same input and seed, same result.
    """

    max_skeletons: int = 20
    time_limit: float = 120.0
    symbolic_weight: float = 0.1
    waypoints: int = 10
    anytime: bool = False
    seed: int = 0

    def __post_init__(self):
        if self.waypoints < 2:
            raise ValueError("waypoints must be >= 2")


class Timers:
    """Seconds per named stage."""

    def __init__(self):
        self.seconds: dict[str, float] = {}

    @contextmanager
    def stage(self, name: str):
        start = time.perf_counter()
        try:
            yield
        finally:
            self.seconds[name] = self.seconds.get(name, 0.0) + time.perf_counter() - start

    def add(self, name: str, seconds: float) -> None:
        self.seconds[name] = self.seconds.get(name, 0.0) + seconds


class _TimedSkeletons:
    """Wraps the top-k generator: counts the time spent producing skeletons."""

    def __init__(self, topk, timers: Timers):
        self.topk, self.timers = topk, timers

    def forbid_prefix(self, names):
        self.topk.forbid_prefix(names)

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


def solve(domain_path: str, problem_path: str, scene_path: str | None = None,
          modes_path: str | None = None, options: SolveOptions = SolveOptions(),
          on_event: Callable[[Event], None] | None = None) -> Solution:
    timers = Timers()
    started = time.perf_counter()
    with timers.stage("parse"):
        domain = parser.parse_domain_file(domain_path)
        problem = parser.parse_problem_file(problem_path)
        _check(domain, problem)
    with timers.stage("ground"):
        from tampcli.task.ground import ground

        task = ground(domain, problem)

    from tampcli.geometry.locate import find_modes, find_scene

    scene_file = scene_path or find_scene(problem_path)
    if scene_file is None:
        return _solve_symbolic(domain_path, problem_path, task, options, timers, started)
    modes_file = modes_path or find_modes(domain_path)
    return _solve_geometric(domain_path, problem_path, str(scene_file),
                            str(modes_file) if modes_file else None, domain, problem, task,
                            options, timers, started, on_event)


def _check(domain, problem) -> None:
    try:
        from tampcli.pddl import check
    except ImportError:
        return
    check.check(domain, problem)


def _solve_symbolic(domain_path, problem_path, task, options, timers, started) -> Solution:
    from tampcli.search.topk import TopK

    with timers.stage("search"):
        plan = next(iter(TopK(task, loopless=True, time_limit=options.time_limit)), None)
    stats = _stats(timers, started, {"symbolic_only": True})
    if plan is None:
        return Solution(domain_path, problem_path, None, "unsolvable",
                        reason="no plan: the task is symbolically unsolvable", stats=stats)
    return Solution(domain_path, problem_path, None, "solved",
                    reason=None, plan=tuple(op.name for op in plan.operators),
                    symbolic_cost=plan.cost, cost=0.0, lower_bound=None, stats=stats,
                    symbolic_weight=options.symbolic_weight,
                    objective=options.symbolic_weight * plan.cost)


def _solve_geometric(domain_path, problem_path, scene_file, modes_file, domain, problem, task,
                     options, timers, started, on_event) -> Solution:
    # "setup": what a process pays once (numpy, scipy, pybullet and FCL imports; the
    # simulator and the collision geometry), reported apart from the solve proper.
    with timers.stage("setup"):
        from tampcli.errors import SceneError
        from tampcli.geometry.collision import CollisionChecker
        from tampcli.geometry.scene import load_modes, load_scene  # numpy, tomllib
        from tampcli.geometry.world import World
        from tampcli.optimize.options import OptimizeOptions
        from tampcli.optimize.problem import lower
        from tampcli.optimize.solve import solve as solve_stage
        from tampcli.search.topk import TopK

    with timers.stage("scene"):
        if modes_file is None:
            raise SceneError("the problem has a scene but the domain has no modes.toml beside "
                             "it (or pass --modes)", domain_path)
        modes = load_modes(modes_file, domain)
        scene = load_scene(scene_file, domain, problem, modes=modes)
    deadline = time.perf_counter() + options.time_limit
    nlp_options = OptimizeOptions(waypoints=options.waypoints, seed=options.seed)

    with timers.stage("setup"):
        world = World(scene)
    with world:
        with timers.stage("setup"):
            checker = CollisionChecker(world)
        lowered: dict[tuple[str, ...], object] = {}

        def evaluate(ops, stage, warm):
            names = tuple(op.name for op in ops)
            if names not in lowered:
                lowered[names] = lower(ops, scene, modes, world, nlp_options, domain=domain,
                                       checker=checker)
            remaining = max(deadline - time.perf_counter(), 0.5)
            stage_options = nlp_options if remaining >= nlp_options.time_limit else \
                _with_time_limit(nlp_options, remaining)
            return solve_stage(lowered[names], stage, warm=warm, options=stage_options)

        def is_geometric(op) -> bool:
            return modes.get_mode(op.action).kind != "none"

        topk = TopK(task, loopless=True, time_limit=options.time_limit)
        bnb_options = BnBOptions(max_skeletons=options.max_skeletons,
                                 time_limit=options.time_limit,
                                 symbolic_weight=options.symbolic_weight,
                                 anytime=options.anytime)
        bnb_start = time.perf_counter()
        result = branch_and_bound(_TimedSkeletons(topk, timers), evaluate, bnb_options,
                                  is_geometric=is_geometric, on_event=on_event)
        timers.add("optimize", result.stats.get("optimize_seconds", 0.0))
        timers.add("bnb", time.perf_counter() - bnb_start)
        robot = {"model": scene.robot.model, "joints": list(world.joint_names),
                 "tool_link": world.tool_link}

    stats = _stats(timers, started, result.stats)
    common = dict(domain=domain_path, problem=problem_path, scene=scene_file, modes=modes_file,
                  robot=robot, skeletons=tuple(result.skeletons), stats=stats,
                  symbolic_weight=options.symbolic_weight, lower_bound=result.lower_bound)
    if result.status != "solved":
        return Solution(status=result.status, reason=result.reason, **common)
    best = result.best
    return Solution(
        status="solved", reason=None, plan=tuple(op.name for op in result.best_plan),
        symbolic_cost=result.best_symbolic_cost, cost=float(best.cost),
        objective=result.best_objective,
        trajectory=tuple(tuple(float(v) for v in q) for q in best.trajectory),
        phases=tuple(p if isinstance(p, Phase) else Phase(*p) for p in best.phases),
        objects={k: [list(map(float, pose)) for pose in v] for k, v in best.object_poses.items()},
        **common)


def _with_time_limit(options, seconds):
    import dataclasses

    return dataclasses.replace(options, time_limit=seconds)


def _stats(timers: Timers, started: float, extra: dict) -> dict:
    seconds = {k: round(v, 4) for k, v in timers.seconds.items()}
    for key in ("parse", "ground", "search", "optimize"):
        seconds.setdefault(key, 0.0)
    seconds["total"] = round(time.perf_counter() - started, 4)
    stats = dict(extra)
    stats["seconds"] = seconds
    return stats
