"""SCIP's best solution -> the plan, trajectory, phases and object poses of a Solution.

The trajectory is the T + 1 robot positions, not subdivided (subdividing a
segment would change its squared-displacement cost). Object positions are
recomputed from the robot's and the discrete decisions, so that a resting
object does not move at all and a carried one keeps its offset exactly (SCIP
meets constraints only to its feasibility tolerance).
"""

from __future__ import annotations

from dataclasses import dataclass

from tampcli.minlp.events import ATTACH, RELEASE, SLIDE, TRAVEL
from tampcli.solution import Phase


@dataclass(frozen=True)
class Extracted:
    plan: tuple[str, ...]
    symbolic_cost: float
    cost: float
    trajectory: tuple[tuple[float, float], ...]
    phases: tuple[Phase, ...]
    objects: dict


def extract(built, task, scene, sol) -> Extracted:
    steps = built.steps
    def value(var) -> float:
        return built.model.getSolVal(sol, var)

    def on(x) -> bool:
        return not isinstance(x, float) and value(x) > 0.5

    r = [tuple(float(v) if isinstance(v, float) else float(value(v)) for v in p)
         for p in built.robot]
    op_at: dict[int, int] = {}
    starts: dict[int, str] = {}
    for k in range(1, steps + 1):
        for i, var in enumerate(built.sym.d[k]):
            if on(var):
                op_at[k] = i
        for name, s in built.carry.start.items():
            if on(s[k]):
                starts[k] = name
    carried = [next((n for n in built.objects if on(built.carry.hold[n][k])
                     or on(built.carry.push[n][k])), None) for k in range(steps)]
    positions = _object_positions(built, r, carried)
    phases = _phases(built, task, op_at, starts, steps)
    objects = {}
    for name, xy in positions.items():
        pose = scene.body(name).pose
        at = [0] + [p.end for p in phases]
        objects[name] = [[xy[k][0], xy[k][1], *pose[2:]] for k in at]
    plan = tuple(task.operators[op_at[k]].name for k in sorted(op_at))
    symbolic_cost = sum(task.operators[op_at[k]].cost for k in op_at)
    cost = sum((r[k + 1][0] - r[k][0]) ** 2 + (r[k + 1][1] - r[k][1]) ** 2
               for k in range(steps))
    return Extracted(plan, float(symbolic_cost), float(cost), tuple(r), tuple(phases), objects)


def _object_positions(built, r, carried) -> dict:
    out = {}
    for name, o in built.objects.items():
        xy = [tuple(float(v) for v in o[0])]
        for k in range(built.steps):
            x, y = xy[k]
            if carried[k] == name:
                dx, dy = x - r[k][0], y - r[k][1]
                xy.append((r[k + 1][0] + dx, r[k + 1][1] + dy))
            else:
                xy.append((x, y))
        out[name] = xy
    return out


def _phases(built, task, op_at, starts, steps) -> list[Phase]:
    """Motion phases between events; instantaneous grasp, place and symbolic-only actions;
    a push spanning its motion from its start; a move spanning the motion before it."""
    phases: list[Phase] = []
    last, holding, push_from = 0, None, None

    def motion_to(k):
        nonlocal last
        if k > last:
            phases.append(Phase(None, last, k, holding))
            last = k

    for k in range(1, steps + 1):
        if k in op_at:
            op = task.operators[op_at[k]]
            g = built.geometry[op_at[k]]
            if g.role == SLIDE:
                phases.append(Phase(op.name, push_from, k, g.obj))
                last, holding = k, None
            elif g.role == TRAVEL:
                phases.append(Phase(op.name, last, k, holding))
                last = k
            else:
                motion_to(k)
                if g.role == ATTACH:
                    holding = g.obj
                elif g.role == RELEASE:
                    holding = None
                phases.append(Phase(op.name, k, k, holding))
        if k in starts:
            motion_to(k)
            push_from, holding = k, starts[k]
    motion_to(steps)
    return phases
