"""What each ground operator does geometrically, and the carry state it switches (§4).

Every action happens at a waypoint k = 1..T. For each movable object o:

    hold[o][k] = hold[o][k-1] + (grasps of o at k) - (places of o at k)    (the lesson's
    push[o][k] = push[o][k-1] + start[o][k] - (pushes of o at k)           h_{k+1} = h_k +
                                                                            grasp - release)
hold and push start at 0; a push ends by T. `start[o][k]` is the push's
beginning (the disk touches o): not a symbolic action, the push operator
itself stands at the push's end, where its effect (o in region `to`)
becomes true. The robot carries at most one object; while it pushes, no
other action happens. Segment k (waypoint k to k + 1) carries o when
hold[o][k] + push[o][k] = 1.
"""

from __future__ import annotations

from dataclasses import dataclass

from pyscipopt import quicksum

from tampcli.optimize.bodies import REST_TOLERANCE
from tampcli.optimize.kinds import KINDS
from tampcli.optimize.kinds.grasp import Grasp
from tampcli.optimize.kinds.move import Move
from tampcli.optimize.kinds.none import Symbolic
from tampcli.optimize.kinds.place import Place
from tampcli.optimize.kinds.push import Push

# What each mode kind is in the time-indexed model: a registry keyed by the kind's
# type (a kind this model cannot express is refused by `op_geometry`).
ATTACH, RELEASE, SLIDE, TRAVEL, IDLE = "attach", "release", "slide", "travel", "idle"
ROLE_OF = {Grasp: ATTACH, Place: RELEASE, Push: SLIDE, Move: TRAVEL, Symbolic: IDLE}


@dataclass(frozen=True)
class OpGeometry:
    role: str  # ATTACH (a grasp) | RELEASE (a place) | SLIDE (a push) | TRAVEL | IDLE
    obj: str | None = None
    target: str | None = None  # a release's `on`; a slide's or travel's `to`


@dataclass(frozen=True)
class Carry:
    """The carry state's variables; index k = 0..T (entries at k = 0 are the constant 0)."""

    hold: dict
    push: dict
    start: dict
    attach: dict  # grasp or push start of o at waypoint k
    release: dict  # place or push end of o at waypoint k

    def carried(self, name: str, k: int):
        return self.hold[name][k] + self.push[name][k]


def op_geometry(task, modes) -> tuple[OpGeometry, ...]:
    out = []
    for op in task.operators:
        mode = modes.get_mode(op.action)
        roles = mode.bind(op.args) if mode.params else {"object": mode.object, "on": mode.on,
                                                         "to": mode.to}
        role = ROLE_OF[type(KINDS[mode.kind])]
        target = roles["on"] if role == RELEASE else roles["to"]
        out.append(OpGeometry(role, roles["object"], target))
    return tuple(out)


def infeasible_ops(geometry, scene, footprints) -> frozenset[int]:
    """Operators no trajectory can carry out: they move a fixed or absent body, or put an
    object on a surface its bottom does not slide on (the planar robot cannot lift)."""
    movable = {b.name for b in scene.bodies if not b.fixed}
    out = set()
    for i, g in enumerate(geometry):
        if g.role in (ATTACH, RELEASE, SLIDE) and g.obj not in movable:
            out.add(i)
        elif g.role in (RELEASE, SLIDE) and g.target is not None:
            support = scene.region(g.target).on if scene.has_region(g.target) else g.target
            if not scene.has_body(support) or support == g.obj:
                out.add(i)
                continue
            top = footprints[support].z_high
            if abs(top - footprints[g.obj].z_low) > REST_TOLERANCE:
                out.add(i)
    return frozenset(out)


def encode_carry(model, geometry, d, movable: list[str], steps: int) -> Carry:
    hold, push, start, attach, release = {}, {}, {}, {}, {}
    for o in movable:
        grasps = [i for i, g in enumerate(geometry) if g.role == ATTACH and g.obj == o]
        places = [i for i, g in enumerate(geometry) if g.role == RELEASE and g.obj == o]
        pushes = [i for i, g in enumerate(geometry) if g.role == SLIDE and g.obj == o]
        h, p, s, att, rel = [0.0], [0.0], [0.0], [0.0], [0.0]
        for k in range(1, steps + 1):
            s.append(model.addVar(f"pstart_{o}_{k}", vtype="B",
                                  ub=1.0 if pushes and k < steps else 0.0))
            h.append(model.addVar(f"hold_{o}_{k}", vtype="B", ub=1.0 if grasps else 0.0))
            p.append(model.addVar(f"push_{o}_{k}", vtype="B", ub=1.0 if pushes and k < steps
                                  else 0.0))
            g_k = quicksum(d[k][i] for i in grasps)
            pl_k = quicksum(d[k][i] for i in places)
            pu_k = quicksum(d[k][i] for i in pushes)
            model.addCons(h[k] == h[k - 1] + g_k - pl_k, name=f"hold_{o}_{k}")
            model.addCons(p[k] == p[k - 1] + s[k] - pu_k, name=f"push_{o}_{k}")
            # A push ends where it was going on; nothing else happens during it.
            model.addCons(pu_k <= p[k - 1], name=f"pushing_{o}_{k}")
            others = [i for i in range(len(geometry)) if i not in pushes]
            if others:
                model.addCons(quicksum(d[k][i] for i in others) <= 1 - p[k - 1],
                              name=f"busy_{o}_{k}")
            att.append(g_k + s[k])
            rel.append(pl_k + pu_k)
        hold[o], push[o], start[o] = tuple(h), tuple(p), tuple(s)
        attach[o], release[o] = tuple(att), tuple(rel)
    for k in range(1, steps + 1):
        if movable:
            model.addCons(quicksum(hold[o][k] + push[o][k] for o in movable) <= 1,
                          name=f"capacity_{k}")
    return Carry(hold, push, start, attach, release)
