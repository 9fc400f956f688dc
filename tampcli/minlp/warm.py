"""A solution.json (e.g. branch and bound's) as SCIP's starting point.

Its actions are put at the waypoints of the MINLP's T steps (scaled from the
file's waypoint count), and, when the file has exactly T + 1 waypoints, its
robot positions too; SCIP completes the rest as a partial solution (its
`completesol` heuristic) and keeps it if it is feasible for the model.
"""

from __future__ import annotations

from tampcli.solution_read import read_solution


def add_warm_start(built, task, path: str) -> str:
    """Give SCIP the file's decisions; returns what was given, in words (for stats)."""
    sol = read_solution(path).raw
    if sol.status != "solved" or not sol.trajectory:
        return f"not used: {path} holds no solved trajectory"
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
            return f"not used: {name} is not a ground action of the task"
        i = index[name]
        geometry = built.geometry[i]
        k = at(phase.end)
        if geometry.kind == "push":
            starts[at(phase.start)] = geometry.obj
        if k in events:
            return f"not used: two actions fall on waypoint {k} of {steps}"
        events[k] = i
    model = built.model
    partial = model.createPartialSol()
    for k in range(1, steps + 1):
        for i, var in enumerate(built.sym.d[k]):
            model.setSolVal(partial, var, float(events.get(k) == i))
        model.setSolVal(partial, built.sym.noop[k], float(k not in events))
        for name, s in built.carry.start.items():
            model.setSolVal(partial, s[k], float(starts.get(k) == name))
    positions = n == steps
    if positions:
        for k in range(1, steps + 1):
            for a in range(2):
                model.setSolVal(partial, built.robot[k][a], float(sol.trajectory[k][a]))
    model.addSol(partial)
    return (f"{len(events)} actions" + (" and the robot's waypoints" if positions else "")
            + f" from {path}")
