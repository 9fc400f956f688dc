"""`solve_minlp`: parse, ground, load the planar scene, build the MINLP, let SCIP solve it.

Honest labels: `lower_bound` is SCIP's dual bound, proved for the model
solved: T steps of straight segments and, with the default "outer" collision
model, round bodies drawn as circumscribed polygons (more constrained than the
true disks). With `collision_model="inner"` (inscribed polygons, a relaxation
of the disks) the bound holds for the true T-step problem, but the solution may
graze a round body.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

from tampcli.errors import InputError, SceneError
from tampcli.minlp.extract import extract
from tampcli.minlp.model import build
from tampcli.minlp.options import MinlpOptions
from tampcli.minlp.warm import add_warm_start, fix_schedule
from tampcli.solution import Solution
from tampcli.task.restrict import op_indices


def solve_minlp(domain_path: str, problem_path: str, scene_path: str | None = None,
                modes_path: str | None = None, options: MinlpOptions | None = None) -> Solution:
    options = options or MinlpOptions()
    started = time.perf_counter()
    prepared = prepare(domain_path, problem_path, scene_path, modes_path, options)
    task, scene, modes = prepared.task, prepared.scene, prepared.modes
    seconds = {"setup": time.perf_counter() - started}

    tic = time.perf_counter()
    built = build(task, scene, modes, prepared.lower, prepared.upper, prepared.start, options,
                  prepared.forced, prepared.forbidden)
    model = built.model
    # CPU seconds: on a shared machine the wall clock would charge SCIP for others' work.
    model.setParam("timing/clocktype", 1)
    model.setParam("limits/time", options.time_limit)
    model.setParam("limits/gap", options.gap)
    model.setParam("randomization/randomseedshift", options.seed)
    warm = add_warm_start(built, task, options.warm_start) if options.warm_start else None
    fixed = fix_schedule(built, task, options.schedule) if options.schedule else None
    seconds["build"] = time.perf_counter() - tic

    tic = time.perf_counter()
    model.optimize()
    seconds["scip"] = time.perf_counter() - tic
    seconds["scip_cpu"] = model.getSolvingTime()
    seconds["total"] = time.perf_counter() - started
    status = model.getStatus()
    has_sol = model.getNSols() > 0
    dual = model.getDualbound()
    stats = {"method": "minlp", "steps": options.steps, "scip_status": status,
             "collision_model": options.collision_model,
             "polygon_sides": options.polygon_sides, "binaries": model.getNBinVars(),
             "variables": model.getNVars(), "constraints": model.getNConss(),
             "nodes": model.getNTotalNodes(), "dual_bound": _finite(dual),
             "primal_bound": _finite(model.getPrimalbound()) if has_sol else None,
             "gap": _finite(model.getGap()) if has_sol else None,
             "warm_start": warm, "schedule": fixed, "seconds": {k: round(v, 4) for k, v in seconds.items()}}
    common = dict(domain=domain_path, problem=problem_path, scene=prepared.scene_file,
                  modes=prepared.modes_file, robot=prepared.robot, stats=stats,
                  symbolic_weight=options.symbolic_weight, lower_bound=_finite(dual))
    if not has_sol:
        if status == "infeasible":
            return Solution(status="unsolvable", reason=f"no plan of at most {options.steps} "
                            "actions with a trajectory of that many steps (proved by SCIP for "
                            "this model)", **{**common, "lower_bound": None})
        return Solution(status="limit", reason=f"SCIP stopped ({status}) without a solution",
                        **common)
    found = extract(built, task, scene, model.getBestSol())
    objective = found.cost + options.symbolic_weight * found.symbolic_cost
    if common["lower_bound"] is not None:
        # The cost recomputed from the waypoints may undercut SCIP's primal value by its
        # feasibility tolerance; a bound above the reported objective would read as a bug.
        common["lower_bound"] = min(common["lower_bound"], objective)
    return Solution(status="solved", reason=None, plan=found.plan,
                    symbolic_cost=found.symbolic_cost, cost=found.cost, objective=objective,
                    trajectory=found.trajectory, phases=found.phases, objects=found.objects,
                    **common)


@dataclass(frozen=True)
class Prepared:
    """The inputs of the model, loaded and checked."""

    task: object
    scene: object
    modes: object
    scene_file: str
    modes_file: str
    lower: tuple[float, float]  # the robot's joint limits (x, y)
    upper: tuple[float, float]
    start: tuple[float, float]
    robot: dict  # solution.json's `robot`
    forced: frozenset[int]
    forbidden: frozenset[int]


def prepare(domain_path, problem_path, scene_path, modes_path, options) -> Prepared:
    from tampcli.geometry.collision import CollisionChecker
    from tampcli.geometry.locate import find_modes, find_scene
    from tampcli.geometry.scene import read_scene
    from tampcli.geometry.startcheck import check_start_state
    from tampcli.geometry.world import World
    from tampcli.minlp.footprint import robot_footprint
    from tampcli.minlp.symbolic import check_supported
    from tampcli.optimize.modes import load_modes
    from tampcli.pddl.load import load
    from tampcli.task.ground import ground

    loaded = load(domain_path, problem_path)
    domain, problem = loaded.domain, loaded.problem
    task = ground(domain, problem)
    check_supported(task, problem_path)
    scene_file = scene_path or find_scene(problem_path)
    if scene_file is None:
        raise InputError("the MINLP needs a scene (none given, none beside the problem)",
                         problem_path)
    modes_file = modes_path or find_modes(domain_path)
    if modes_file is None:
        raise SceneError("the problem has a scene but the domain has no modes.toml beside it "
                         "(or pass --modes)", domain_path)
    modes = load_modes(modes_file, domain)
    scene, source = read_scene(str(scene_file), domain, problem, modes=modes)
    robot_footprint(scene, options.polygon_sides, True)  # a non-planar robot: refused here
    with World(scene, visuals=False) as world:
        check_start_state(world, CollisionChecker(world), source)
        limits = (tuple(map(float, world.lower)), tuple(map(float, world.upper)),
                  tuple(map(float, world.start)))
        robot = {"model": scene.robot.model, "joints": list(world.joint_names),
                 "tool_link": world.tool_link}
    return Prepared(task, scene, modes, str(scene_file), str(modes_file), *limits, robot,
                    op_indices(task, options.forced, "--force"),
                    op_indices(task, options.forbidden, "--forbid"))


def _finite(x: float) -> float | None:
    return float(x) if abs(x) < 1e19 else None
