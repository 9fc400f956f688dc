"""The lesson's time-indexed hybrid program for the planar robot, built in SCIP.

    min  sum_k ||r[k+1] - r[k]||^2 + w * sum_k sum_i cost_i d[k][i]

over robot positions r[0..T] (r[0] the start), object positions o[j][0..T],
the task's fact and action variables (symbolic.py) and the carry state
(events.py), subject to:

- a carried object keeps its offset to the disk over a segment; any other
  object stays where it is;
- grasp and push start (attach) put the disk within reach of the object
  (`radius` + its largest half extent: the MINLP's own, conservative reach; the
  optimizer's touch depends on the face, docs/formats.md "Grasp");
  the disk must also stay outside the object's footprint (collide.py), so it
  touches the object's side;
- place and push end put the object's footprint inside the target region
  (or inside the target body's top face, as a stacked footprint); a move with
  `to` ends the disk over its target;
- no collision along any segment: the disk against every body it is not
  carrying, and the carried object against every other body, except what
  the robot slides on (bodies whose height span only touches theirs).

Each implication is big-M with M from the variable bounds (bigm.py). Each
segment's cost also bounds the squared displacement of the objects in it (an
object moves only with the disk): a valid inequality free of big-M.
"""

from __future__ import annotations

from dataclasses import dataclass

from pyscipopt import Model, quicksum

from tampcli.minlp import symbolic
from tampcli.minlp.bigm import implies_close, implies_eq, implies_le
from tampcli.minlp.collide import separate
from tampcli.minlp.events import (
    RELEASE,
    SLIDE,
    TRAVEL,
    Carry,
    OpGeometry,
    encode_carry,
    infeasible_ops,
    op_geometry,
)
from tampcli.minlp.footprint import Footprint, body_footprint, overlaps_in_height, robot_footprint
from tampcli.minlp.push_cone import encode_push_cones


@dataclass(frozen=True)
class Built:
    """The model and the variables solution extraction reads."""

    model: Model
    steps: int
    robot: tuple  # r[k] = (x, y), k = 0..T
    objects: dict  # name -> o[k] = (x, y)
    sym: symbolic.SymbolicVars
    carry: Carry
    geometry: tuple[OpGeometry, ...]
    segment_cost: tuple  # s[k] >= ||r[k+1] - r[k]||^2
    binaries: int  # collision binaries


def build(task, scene, modes, lower, upper, start, options, forced=frozenset(),
          forbidden=frozenset()) -> Built:
    """`lower`, `upper`: the robot's joint limits (x, y); `start`: its start (x, y)."""
    sides, outer = options.polygon_sides, options.collision_model == "outer"
    robot_shape = robot_footprint(scene, sides, outer)
    shapes = {b.name: body_footprint(b, scene.path, sides, outer) for b in scene.bodies}
    geometry = op_geometry(task, modes)
    disabled = infeasible_ops(geometry, scene, shapes) | forbidden
    steps = options.steps
    model = Model("tamp-minlp")
    model.hideOutput()
    sym = symbolic.encode_task(model, task, steps, frozenset(disabled))
    for i in forced:
        model.addCons(quicksum(sym.d[k][i] for k in range(1, steps + 1)) >= 1, name=f"force_{i}")
    movable = [b.name for b in scene.bodies if not b.fixed]
    carry = encode_carry(model, geometry, sym.d, movable, steps)

    r = [(float(start[0]), float(start[1]))]
    for k in range(1, steps + 1):
        r.append(tuple(model.addVar(f"r{a}_{k}", lb=lower[a], ub=upper[a]) for a in range(2)))
    objects = {}
    for name in movable:
        body = scene.body(name)
        reach = robot_shape.reach + shapes[name].reach
        o = [(float(body.pose[0]), float(body.pose[1]))]
        for k in range(1, steps + 1):
            o.append(tuple(model.addVar(f"o_{name}{a}_{k}", lb=lower[a] - reach,
                                        ub=upper[a] + reach) for a in range(2)))
        objects[name] = o

    _motion(model, r, objects, carry, steps)
    _contacts(model, r, objects, carry, robot_shape, shapes, steps)
    _targets(model, r, objects, sym, geometry, scene, shapes, steps, disabled)
    encode_push_cones(model, r, objects, carry, float(scene.robot.radius), shapes, steps)
    binaries = _collisions(model, r, objects, carry, robot_shape, shapes, scene, steps)

    _decide_first(model, sym, carry, steps)
    cost = []
    for k in range(steps):
        s = model.addVar(f"seg_{k}", lb=0.0)
        model.addCons(quicksum((r[k + 1][a] - r[k][a]) * (r[k + 1][a] - r[k][a])
                               for a in range(2)) <= s, name=f"segcost_{k}")
        if objects:
            # Valid without big-M: at most one object moves in a segment, and only as far
            # as the disk does; it lets the relaxation see that what must reach the goal
            # drags the robot along.
            model.addCons(quicksum((o[k + 1][a] - o[k][a]) * (o[k + 1][a] - o[k][a])
                                   for o in objects.values() for a in range(2)) <= s,
                          name=f"dragged_{k}")
        cost.append(s)
    symbolic_cost = quicksum(op.cost * sym.d[k][i] for k in range(1, steps + 1)
                             for i, op in enumerate(task.operators))
    model.setObjective(quicksum(cost) + options.symbolic_weight * symbolic_cost, "minimize")
    return Built(model, steps, tuple(r), objects, sym, carry, geometry, tuple(cost), binaries)


def _decide_first(model, sym, carry: Carry, steps: int) -> None:
    """Branch on what happens when before on which face a segment passes: once the
    actions are fixed, the rest is a much smaller problem."""
    for k in range(1, steps + 1):
        for var in (*sym.d[k], *(carry.start[o][k] for o in carry.start)):
            model.chgVarBranchPriority(var, 10)


def _diff(a, b, c, d_, axis):
    """Terms of (a - b) - (c - d_) along `axis` for points that may hold constants."""
    terms, constant = [], 0.0
    for coef, p in ((1.0, a), (-1.0, b), (-1.0, c), (1.0, d_)):
        if p is None:
            continue
        x = p[axis]
        if isinstance(x, float):
            constant += coef * x
        else:
            terms.append((coef, x))
    return terms, constant


def _motion(model, r, objects, carry: Carry, steps: int) -> None:
    for name, o in objects.items():
        for k in range(steps):
            c = carry.carried(name, k)
            for a in range(2):
                terms, const = _diff(o[k + 1], o[k], r[k + 1], r[k], a)
                if terms:
                    implies_eq(model, c, terms, -const, f"rigid_{name}_{k}_{a}")
                terms, const = _diff(o[k + 1], o[k], None, None, a)
                implies_eq(model, 1 - c, terms, -const, f"stay_{name}_{k}_{a}")


def _contacts(model, r, objects, carry: Carry, robot_shape: Footprint, shapes, steps) -> None:
    for name, o in objects.items():
        reach = robot_shape.reach + shapes[name].reach
        for k in range(1, steps + 1):
            implies_close(model, carry.attach[name][k], r[k], o[k], reach, f"touch_{name}_{k}")


def _targets(model, r, objects, sym, geometry, scene, shapes, steps, disabled) -> None:
    for i, g in enumerate(geometry):
        if g.target is None or g.role not in (RELEASE, SLIDE, TRAVEL) or i in disabled:
            continue
        if scene.has_region(g.target):
            region = scene.region(g.target)
            lo, hi = region.lower, region.upper
            ext = shapes[g.obj].extent if g.role != TRAVEL else (0.0, 0.0)
        else:  # a body's top face: the whole footprint on it, as optimize/stability.py
            body = scene.body(g.target)
            ext = shapes[g.obj].extent if g.role != TRAVEL else (0.0, 0.0)
            half = shapes[g.target].extent
            lo = [body.pose[a] - half[a] for a in range(2)]
            hi = [body.pose[a] + half[a] for a in range(2)]
        for k in range(1, steps + 1):
            point = r[k] if g.role == TRAVEL else objects[g.obj][k]
            for a in range(2):
                implies_le(model, sym.d[k][i], [(1.0, point[a])], hi[a] - ext[a],
                           f"in_{i}_{k}_{a}_hi")
                implies_le(model, sym.d[k][i], [(-1.0, point[a])], -(lo[a] + ext[a]),
                           f"in_{i}_{k}_{a}_lo")


def _collisions(model, r, objects, carry: Carry, robot_shape, shapes, scene, steps) -> int:
    fixed = [b.name for b in scene.bodies if b.fixed]
    count = 0
    for k in range(steps):
        ends = (r[k], r[k + 1])
        for name in fixed:
            if overlaps_in_height(robot_shape, shapes[name]):
                centre = (float(scene.body(name).pose[0]), float(scene.body(name).pose[1]))
                count += separate(model, ends, centre, robot_shape, shapes[name], 1.0,
                                  f"rf_{name}_{k}")
        for name, o in objects.items():
            c = carry.carried(name, k)
            if overlaps_in_height(robot_shape, shapes[name]):
                count += separate(model, ends, o[k], robot_shape, shapes[name], 1 - c,
                                  f"ro_{name}_{k}")
            moved = (o[k], o[k + 1])
            for other in fixed:
                if overlaps_in_height(shapes[name], shapes[other]):
                    body = scene.body(other)
                    centre = (float(body.pose[0]), float(body.pose[1]))
                    count += separate(model, moved, centre, shapes[name], shapes[other], c,
                                      f"of_{name}_{other}_{k}")
            for other, p in objects.items():
                if other != name and overlaps_in_height(shapes[name], shapes[other]):
                    count += separate(model, moved, p[k], shapes[name], shapes[other], c,
                                      f"oo_{name}_{other}_{k}")
    return count
