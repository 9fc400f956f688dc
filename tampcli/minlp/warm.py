"""A solution.json (e.g. branch and bound's) as SCIP's start, or as a fixed schedule.

Its actions are put at the waypoints of the MINLP's T steps (scaled from the
file's waypoint count; a push also fixes where it starts). As a warm start,
they and, when the file has exactly T + 1 waypoints, its robot positions are a
partial solution SCIP completes (its `completesol` heuristic) and keeps if it
is feasible for the model. As a fixed schedule they are imposed: what is left
is the trajectory for that sequence of decisions, the lesson's V(d) of §2,
solved globally.
"""

from __future__ import annotations

from dataclasses import dataclass

from tampcli.minlp.events import SLIDE
from tampcli.solution_read import read_solution


@dataclass(frozen=True)
class Schedule:
    events: dict  # waypoint -> operator index
    starts: dict  # waypoint -> object whose push starts there
    trajectory: tuple  # the file's waypoints


def read_schedule(built, task, path: str) -> Schedule | str:
    """The file's decisions on the model's waypoints, or why they cannot be used."""
    sol = read_solution(path).raw
    if sol.status != "solved" or not sol.trajectory:
        return f"{path} holds no solved trajectory"
    steps, n = built.steps, len(sol.trajectory) - 1
    index = {op.name: i for i, op in enumerate(task.operators)}

    def at(j: int) -> int:
        return min(max(round(j * steps / max(n, 1)), 1), steps)

    events: dict[int, int] = {}
    starts: dict[int, str] = {}
    for phase in sol.phases:
        if phase.action is None:
            continue
        name = "(" + " ".join(phase.action.strip("()").lower().split()) + ")"
        if name not in index:
            return f"{name} is not a ground action of the task"
        i = index[name]
        k = at(phase.end)
        if built.geometry[i].role == SLIDE:
            starts[at(phase.start)] = built.geometry[i].obj
        if k in events:
            return f"two actions fall on waypoint {k} of {steps}"
        events[k] = i
    return Schedule(events, starts, sol.trajectory)


def _decisions(built, schedule: Schedule):
    for k in range(1, built.steps + 1):
        for i, var in enumerate(built.sym.d[k]):
            yield var, float(schedule.events.get(k) == i)
        yield built.sym.noop[k], float(k not in schedule.events)
        for name, s in built.carry.start.items():
            yield s[k], float(schedule.starts.get(k) == name)


def add_warm_start(built, task, path: str) -> str:
    """Give SCIP the file's decisions; returns what was given, in words (for stats)."""
    schedule = read_schedule(built, task, path)
    if isinstance(schedule, str):
        return f"not used: {schedule}"
    model = built.model
    partial = model.createPartialSol()
    for var, value in _decisions(built, schedule):
        model.setSolVal(partial, var, value)
    positions = len(schedule.trajectory) == built.steps + 1
    if positions:
        for k in range(1, built.steps + 1):
            for a in range(2):
                model.setSolVal(partial, built.robot[k][a], float(schedule.trajectory[k][a]))
    model.addSol(partial)
    return (f"{len(schedule.events)} actions" + (" and the robot's waypoints" if positions
                                                 else "") + f" from {path}")


def fix_schedule(built, task, path: str) -> str:
    """Impose the file's decisions; a file that cannot give them is bad input."""
    from tampcli.errors import InputError

    schedule = read_schedule(built, task, path)
    if isinstance(schedule, str):
        raise InputError(f"cannot fix the schedule: {schedule}", path, key="phases")
    for var, value in _decisions(built, schedule):
        built.model.fixVar(var, value)
    return f"{len(schedule.events)} actions fixed at their waypoints from {path}"
