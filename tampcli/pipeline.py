"""The whole TAMP pipeline in one place: each stage run in order, timed by name.

    parse -> ground -> scene -> World + start check
          -> (top-k skeletons x trajectory NLPs: branch and bound) -> Solution

A solve reads each input once and builds one World and one CollisionChecker;
`solving` keeps that World open for its caller (`solve --video` renders in it).
Heavy modules (numpy, pybullet, scipy) are imported only when a scene exists.
Nothing here prints: progress leaves as `bnb.Event`s through `on_event`.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import TYPE_CHECKING

from tampcli.bnb import BnBOptions, BnBResult, Event, branch_and_bound
from tampcli.optimize.options import OptimizeOptions
from tampcli.pddl import ast
from tampcli.pddl.load import load
from tampcli.solution import Phase, Solution
from tampcli.stage_evaluator import Geometry, StageEvaluator

if TYPE_CHECKING:  # numpy, pybullet and FCL behind these: imported only for a scene
    from tampcli.geometry.model import Scene
    from tampcli.geometry.tomlsrc import TomlSource
    from tampcli.geometry.world import World
    from tampcli.optimize.modes import Modes
    from tampcli.task.task import Task


@dataclass(frozen=True)
class SolveOptions:
    """Options of one solve: one checked value per stage.

    bnb: the skeleton search; its `time_limit` (s) bounds the whole solve,
        drawing skeletons included, and its `symbolic_weight` also prices a
        symbolic-only solution.
    optimize: the trajectory NLPs; its `time_limit` (s) caps one stage of one
        skeleton, and is cut to what is left of the solve's.
    forced, forbidden: ground action names every plan must contain and none may
        (`--force`, `--forbid`: the task restricted before any search).
    """

    bnb: BnBOptions = BnBOptions()
    optimize: OptimizeOptions = OptimizeOptions()
    forced: tuple[str, ...] = ()
    forbidden: tuple[str, ...] = ()


@dataclass(frozen=True)
class InputPaths:
    """The files of a solve; a scene or modes file left out is looked for beside
    the problem (`PROBLEM.scene.toml`) or the domain (`modes.toml`)."""

    domain: str
    problem: str
    scene: str | None = None
    modes: str | None = None


@dataclass(frozen=True)
class ParsedInputs:
    """Everything a solve reads, each file read once.

    `scene` is None when the problem has no scene (a symbolic solve); then
    `modes` and `scene_source` are None too. `scene_source` (a TomlSource)
    places start-state errors on the scene file's lines.
    """

    paths: InputPaths  # with the scene and modes files found filled in
    domain: ast.Domain
    problem: ast.Problem
    task: Task
    scene: Scene | None = None
    modes: Modes | None = None
    scene_source: TomlSource | None = None


@dataclass(frozen=True)
class Solved:
    """What `solving` yields: the solution, the inputs it came from, and the
    solve's World (None for a symbolic solve), open until the block ends."""

    solution: Solution
    inputs: ParsedInputs
    world: World | None = None


class Timers:
    """Seconds per named stage, since the timers were made."""

    def __init__(self):
        self.started = time.perf_counter()
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


def solve(paths: InputPaths, options: SolveOptions = SolveOptions(),
          on_event: Callable[[Event], None] | None = None) -> Solution:
    """Solve and close the World: the Solution alone."""
    with solving(paths, options, on_event) as solved:
        return solved.solution


@contextmanager
def solving(paths: InputPaths, options: SolveOptions = SolveOptions(),
            on_event: Callable[[Event], None] | None = None,
            visuals: bool = False) -> Iterator[Solved]:
    """Read the inputs, build the World and CollisionChecker (once each), check
    the start state, search; yield the result with the World still open.
    `visuals`: the World keeps its visual shapes (a caller that renders in it);
    without them a Panda loads in 0.01 s instead of 0.17.

    Raises InputError (bad PDDL, scene, modes, start state) before any search.
    """
    timers = Timers()
    inputs = read_inputs(paths, timers)
    if options.forced or options.forbidden:
        from tampcli.task.restrict import restrict

        inputs = dataclasses.replace(inputs, task=restrict(inputs.task, options.forced,
                                                           options.forbidden))
    if inputs.scene is None:
        yield Solved(_solve_symbolic(inputs, options, timers), inputs)
        return
    with timers.stage("setup"):
        # What a process pays once (pybullet and FCL imports; the simulator and the
        # collision geometry), reported apart from the solve proper.
        from tampcli.geometry.collision import CollisionChecker
        from tampcli.geometry.startcheck import check_start_state
        from tampcli.geometry.world import World

        world = World(inputs.scene, visuals=visuals)
    with world:
        with timers.stage("setup"):
            checker = CollisionChecker(world)
        with timers.stage("scene"):
            check_start_state(world, checker, inputs.scene_source)
        solution = _solve_geometric(inputs, Geometry(world, checker), options, timers,
                                    on_event)
        yield Solved(solution, inputs, world)


def read_inputs(paths: InputPaths, timers: Timers) -> ParsedInputs:
    """Parse and check the PDDL, ground it, and load the scene and modes when the
    problem has a scene."""
    with timers.stage("parse"):
        loaded = load(paths.domain, paths.problem)
        domain, problem = loaded.domain, loaded.problem
    with timers.stage("ground"):
        from tampcli.task.ground import ground

        task = ground(domain, problem)

    from tampcli.geometry.locate import find_modes, find_scene

    scene_file = paths.scene or find_scene(paths.problem)
    if scene_file is None:
        return ParsedInputs(paths, domain, problem, task)
    modes_file = paths.modes or find_modes(paths.domain)
    found = InputPaths(paths.domain, paths.problem, str(scene_file),
                       str(modes_file) if modes_file else None)
    with timers.stage("setup"):
        from tampcli.errors import SceneError
        from tampcli.geometry.scene import read_scene  # numpy, tomllib
        from tampcli.optimize.modes import load_modes
    with timers.stage("scene"):
        if modes_file is None:
            raise SceneError("the problem has a scene but the domain has no modes.toml beside "
                             "it (or pass --modes)", paths.domain)
        modes = load_modes(modes_file, domain)
        scene, source = read_scene(scene_file, domain, problem, modes=modes)
    return ParsedInputs(found, domain, problem, task, scene, modes, source)


def _solve_symbolic(inputs: ParsedInputs, options: SolveOptions, timers: Timers) -> Solution:
    from tampcli.search.topk import TopK

    paths, weight = inputs.paths, options.bnb.symbolic_weight
    with timers.stage("search"):
        plan = next(iter(TopK(inputs.task, loopless=True, time_limit=options.bnb.time_limit)),
                    None)
    stats = _stats(timers, {"symbolic_only": True})
    if plan is None:
        return Solution(paths.domain, paths.problem, None, "unsolvable",
                        reason="no plan: the task is symbolically unsolvable", stats=stats)
    return Solution(paths.domain, paths.problem, None, "solved",
                    reason=None, plan=tuple(op.name for op in plan.operators),
                    symbolic_cost=plan.cost, cost=0.0, lower_bound=None, stats=stats,
                    symbolic_weight=weight, objective=weight * plan.cost)


def _solve_geometric(inputs: ParsedInputs, geometry: Geometry, options: SolveOptions,
                     timers: Timers, on_event: Callable[[Event], None] | None) -> Solution:
    with timers.stage("setup"):
        from tampcli.bnb.eliminate import ELIMINATION_SHARE, eliminate_useless
        from tampcli.bnb.lessons import first_move_proofs, named_lessons, teacher
        from tampcli.geometry.reach import reach_ball
        from tampcli.optimize.bodies import body_info
        from tampcli.search.eliminate import without_step
        from tampcli.search.learned import LearningSource
        from tampcli.search.timed import TimedSource
        from tampcli.search.topk import TopK

        deadline = time.perf_counter() + options.bnb.time_limit
        # The search leaves the last part of the time to action elimination: an answer
        # with actions that serve nothing is worse than a slightly less polished one
        # (blind7 p03: 60 s searched, the useless drop and fetch kept for want of time).
        reserve = ELIMINATION_SHARE * options.bnb.time_limit \
            if math.isfinite(options.bnb.time_limit) else 0.0
        searching = dataclasses.replace(options.bnb, reserve=reserve,
                                        jobs=options.bnb.processes())
        evaluate = StageEvaluator(inputs, geometry, options, deadline)
    modes = inputs.modes
    movable = frozenset(geometry.world.movable_names)

    def make_topk(task):
        return TopK(task, loopless=True, time_limit=max(deadline - time.perf_counter(), 1e-3))

    def moves(op) -> frozenset[str]:
        mode = modes.get_mode(op.action)
        moved = mode.bind(op.args)["object"] if mode.geometric and mode.object else None
        return frozenset({moved}) if moved in movable else frozenset()

    def make_regrasps(task):
        return TopK(task, loopless=True, revisits=1,
                    time_limit=max(deadline - time.perf_counter(), 1e-3))

    source = LearningSource(inputs.task, make_topk, moves, make_regrasps=make_regrasps)

    with timers.stage("setup"):  # proofs before any skeleton (bnb/lessons.py)
        infos = {b.name: body_info(b, geometry.world) for b in inputs.scene.bodies}
        source.require_moved(first_move_proofs(
            inputs.task, modes, inputs.scene, {n: infos[n] for n in movable},
            options.optimize, reach_ball(geometry.world)))
    learn = teacher(source, inputs.task, modes, movable, inputs.scene, infos, evaluate.rows)

    def heard(event) -> None:
        # With an answer the NLPs stop where the search does: the reserve is action
        # elimination's (blind7 p03: a skeleton's path NLPs ran to the end of the time).
        if event.kind == "incumbent":
            evaluate.deadline = min(evaluate.deadline, deadline - reserve)
        if on_event is not None:
            on_event(event)

    bnb_start = time.perf_counter()
    search = dict(is_geometric=lambda op: modes.get_mode(op.action).geometric,
                  on_event=heard, learn=learn, relax=evaluate.relaxed,
                  diagnose=evaluate.violated)
    skeletons = TimedSource(source, timers)
    if searching.jobs == 1:
        result = branch_and_bound(skeletons, evaluate, searching, **search)
    else:
        from tampcli.bnb.parallel import parallel_branch_and_bound
        from tampcli.skeleton_pool import SkeletonPool

        # This process solves skeletons too: jobs - 1 workers (bnb/parallel.py).
        with SkeletonPool(_worker_parts, (inputs.paths, options), searching.jobs - 1,
                          deadline) as pool:
            result = parallel_branch_and_bound(skeletons, pool, evaluate, searching, **search)
    result.stats.update({f"learning_{k}": v for k, v in source.stats.items()})
    result.stats.update(named_lessons(source))
    evaluate.deadline = deadline
    searched = _names(result.best_plan)
    result = eliminate_useless(result, evaluate,
                               lambda ops, i: without_step(inputs.task, ops, i),
                               options.bnb.symbolic_weight, deadline,
                               {op.name: op for op in inputs.task.operators}, movable)
    timers.add("optimize", result.stats.get("optimize_seconds", 0.0))
    timers.add("bnb", time.perf_counter() - bnb_start)
    first = result.stats.get("first_solution_seconds")
    if first is not None:  # what a user waits: from the solve's start (parsing included)
        result.stats["first_solution_since_start"] = round(bnb_start - timers.started + first, 4)
    if result.status == "solved" and result.improvements:
        # When the answer returned was found: the search's last improvement, or, where
        # action elimination changed it, by the end of elimination (blind30 DOC_GAPS 11).
        found = time.perf_counter() if _names(result.best_plan) != searched \
            else bnb_start + result.improvements[-1][0]
        result.stats["answer_since_start"] = round(found - timers.started, 4)
    return _solution(inputs, geometry.world, options, result, _stats(timers, result.stats))


def _names(plan) -> tuple[str, ...]:
    return tuple(op.name for op in plan or ())


def _worker_parts(paths: InputPaths, options: SolveOptions, deadline: float):
    """What a skeleton_pool worker builds once, in its own process: (an evaluator
    over a World and CollisionChecker of its own, the operators by name, which are
    geometric)."""
    from tampcli.geometry.collision import CollisionChecker
    from tampcli.geometry.world import World

    inputs = read_inputs(paths, Timers())
    world = World(inputs.scene, visuals=False)
    evaluate = StageEvaluator(inputs, Geometry(world, CollisionChecker(world)), options, deadline)
    modes = inputs.modes
    return (evaluate, {op.name: op for op in inputs.task.operators},
            lambda op: modes.get_mode(op.action).geometric)


def _solution(inputs: ParsedInputs, world: World, options: SolveOptions, result: BnBResult,
              stats: dict) -> Solution:
    paths = inputs.paths
    robot = {"model": inputs.scene.robot.model, "joints": list(world.joint_names),
             "tool_link": world.tool_link}
    common = dict(domain=paths.domain, problem=paths.problem, scene=paths.scene,
                  modes=paths.modes, robot=robot, skeletons=tuple(result.skeletons),
                  stats=stats, symbolic_weight=options.bnb.symbolic_weight,
                  lower_bound=result.lower_bound)
    if result.status != "solved":
        return Solution(status=result.status, reason=result.reason, **common)
    best = result.best
    trajectory = [[float(v) for v in q] for q in best.trajectory]
    if best.fingers is not None:
        # The hand held narrower than open (optimize/hand.py): its finger joints as
        # columns after the arm's, as the format allows (solution_read.FINGERS_OF); the
        # joints that mimic them follow on reading (solution_fit.finger_rows).
        k = len(world.finger_names)
        common["robot"] = {**robot, "joints": [*robot["joints"], *world.finger_names]}
        trajectory = [q + [float(v) for v in f[:k]]
                      for q, f in zip(trajectory, best.fingers, strict=True)]
    return Solution(
        status="solved", reason=None, plan=tuple(op.name for op in result.best_plan),
        symbolic_cost=result.best_symbolic_cost, cost=float(best.cost),
        objective=result.best_objective,
        trajectory=tuple(tuple(q) for q in trajectory),
        phases=tuple(p if isinstance(p, Phase) else Phase(*p) for p in best.phases),
        objects={k: [list(map(float, pose)) for pose in v] for k, v in best.object_poses.items()},
        kkt=best.kkt, grasps=tuple(best.grasp_report), **common)


def _stats(timers: Timers, extra: dict) -> dict:
    seconds = {k: round(v, 4) for k, v in timers.seconds.items()}
    for key in ("parse", "ground", "search", "optimize"):
        seconds.setdefault(key, 0.0)
    seconds["total"] = round(time.perf_counter() - timers.started, 4)
    stats = dict(extra)
    stats["seconds"] = seconds
    return stats
