"""Lowering: a skeleton (sequence of ground actions) -> TrajectoryProblem.

Phases (docs/formats.md, "solution.json"): before each grasp, place or push a motion phase
of T waypoints is inserted (free, or carrying what is held); a push then
spans its own pushing motion; a move *is* a motion phase; mode switches and
symbolic actions are instantaneous. Each motion phase ends at a keyframe
(its last waypoint), so keyframes and motion phases are one-to-one.

A skeleton that cannot be lowered (placing what is not held, a region the
scene lacks) gives a problem with `error` set: the solver returns it as
infeasible (`proved`), never raises.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from tampcli.optimize.bodies import REST_TOLERANCE, body_info, start_support
from tampcli.optimize.options import OptimizeOptions

GEOMETRIC = ("grasp", "place", "push", "move")
PANDA_OPENING = 0.08  # m, fingers fully open
PANDA_FINGER_DEPTH = 0.015  # m, at most this far below the object's top is the grasp point
PANDA_FINGERTIP = 0.01  # m, fingertips below the grasp target (collision mesh, measured)
PUSH_STANDOFF = 0.012  # m, tool origin to the pushed face (finger half thickness)


@dataclass(frozen=True)
class Step:
    """One action of the skeleton, resolved against the scene."""

    index: int
    name: str  # "(pick a table)"
    kind: str  # grasp | place | push | move | none
    obj: str | None = None
    target: str | None = None  # place: region or body; push/move: region (or None)
    support: str | None = None  # the body under the object after the action (place/push)
    held_before: str | None = None
    held_after: str | None = None
    grasp_step: int | None = None  # place: the step whose grip holds obj; push: itself
    keyframes: tuple[int, ...] = ()  # keyframe indices this step constrains
    rest_z: float | None = None  # place/push: object centre height when resting after


@dataclass(frozen=True)
class MotionPhase:
    """A motion of T waypoints ending at keyframe `index`."""

    index: int
    step: int  # the step that follows (grasp/place/push approach) or owns it (move/push)
    attached: str | None  # held or pushed object (moves with the tool)
    grip_step: int | None  # step whose grip relates `attached` to the tool
    kind: str  # "free" | "carry" | "push"
    enter_contact: frozenset[str] = frozenset()  # bodies allowed to touch in the last segment
    leave_contact: frozenset[str] = frozenset()  # ... in the first segment
    sliding: frozenset[str] = frozenset()  # bodies `attached` slides on (push; planar carry)


@dataclass(frozen=True)
class TrajectoryProblem:
    names: tuple[str, ...]  # action names of the skeleton
    steps: tuple[Step, ...]
    motions: tuple[MotionPhase, ...]
    bodies: dict = field(repr=False)  # name -> BodyInfo
    start_supports: dict = field(repr=False)  # movable name -> body below at the start
    scene: object = field(repr=False)
    world: object = field(repr=False)
    options: OptimizeOptions = OptimizeOptions()
    planar: bool = False
    error: str | None = None  # the skeleton cannot be lowered (infeasible, proved)
    grip_params: tuple[int, ...] = ()  # steps with one continuous grip parameter, in order
    checker: object = field(default=None, repr=False)  # geometry.collision.CollisionChecker

    @property
    def n(self) -> int:
        return self.world.n

    @property
    def n_keyframes(self) -> int:
        return len(self.motions)

    def step_of_keyframe(self, k: int) -> Step:
        return self.steps[self.motions[k].step]


def lower(skeleton, scene, modes, world, options: OptimizeOptions | None = None,
          domain=None, checker=None) -> TrajectoryProblem:
    """Resolve every action's mode against the scene; see the module docstring.

    A mode's `?param` is taken from the action's arguments by position: the
    positions come from `mode.params` when the Mode records them, else from
    `domain.action(name).params`. Pass `checker` to share one CollisionChecker
    of `world` between skeletons (building one loads every collision shape).
    """
    from tampcli.geometry.collision import CollisionChecker

    options = options or OptimizeOptions()
    checker = checker if checker is not None else CollisionChecker(world)
    infos = {b.name: body_info(b, world) for b in scene.bodies}
    supports = {b.name: start_support(infos[b.name], infos) for b in scene.bodies if not b.fixed}
    planar = scene.robot.model == "planar"
    names = tuple(op.name for op in skeleton)
    base = dict(names=names, bodies=infos, start_supports=supports, scene=scene, world=world,
                options=options, planar=planar, checker=checker)
    try:
        steps, motions, grip_params = _lower_steps(skeleton, scene, modes, domain, infos,
                                                   supports, planar)
    except _Infeasible as err:
        return TrajectoryProblem(steps=(), motions=(), error=str(err), **base)
    return TrajectoryProblem(steps=steps, motions=motions, grip_params=grip_params, **base)


class _Infeasible(Exception):
    pass


def mode_of(modes, action: str):
    if modes is None:
        return None
    getter = getattr(modes, "get", None)
    mode = getter(action) if getter else None
    if mode is None or getattr(mode, "kind", "none") == "none":
        return None
    return mode


def _resolve(value: str | None, op, mode, domain) -> str | None:
    if value is None:
        return None
    if not value.startswith("?"):
        return value.lower()
    params = getattr(mode, "params", None)
    if params is None and domain is not None and domain.action(op.action) is not None:
        params = tuple(p.name for p in domain.action(op.action).params)
    if params is None:
        raise _Infeasible(f"{op.name}: cannot resolve {value} without the action's parameters")
    params = tuple(getattr(p, "name", p) for p in params)
    if value not in params:
        raise _Infeasible(f"{op.name}: the action has no parameter {value}")
    return str(op.args[params.index(value)]).lower()


def _lower_steps(skeleton, scene, modes, domain, infos, supports, planar):
    steps: list[Step] = []
    motions: list[MotionPhase] = []
    grip_params: list[int] = []
    held: str | None = None
    held_grip: int | None = None
    support = dict(supports)  # body under each movable object, as the skeleton goes
    rest_z = {n: info.pose[2] for n, info in infos.items()}
    last_contact: frozenset[str] = frozenset()  # bodies touched at the previous keyframe
    regions = {r.name: r for r in scene.regions}

    def motion(step_index, kind, attached, grip, enter, sliding=()):
        if planar and kind == "carry":
            # The planar robot cannot lift: what it carries slides over every
            # surface at the height of its bottom (across tables that touch).
            bottom = rest_z[attached] - infos[attached].half[2]
            sliding = {n for n, b in infos.items()
                       if n != attached and abs(b.top - bottom) <= REST_TOLERANCE}
        m = MotionPhase(len(motions), step_index, attached, grip, kind, frozenset(enter),
                        last_contact, frozenset(sliding) - {None})
        motions.append(m)
        return m.index

    for i, op in enumerate(skeleton):
        mode = mode_of(modes, op.action)
        kind = mode.kind if mode is not None else "none"
        label = f"{op.name}"
        if kind == "none":
            steps.append(Step(i, op.name, "none", held_before=held, held_after=held))
            continue
        obj = _resolve(getattr(mode, "object", None), op, mode, domain)
        on = _resolve(getattr(mode, "on", None), op, mode, domain)
        to = _resolve(getattr(mode, "to", None), op, mode, domain)
        if kind in ("grasp", "place", "push"):
            if obj is None or obj not in infos:
                raise _Infeasible(f"{label}: the scene has no object {obj!r}")
            if infos[obj].fixed:
                raise _Infeasible(f"{label}: {obj} is fixed")
        if kind == "grasp":
            if held is not None:
                raise _Infeasible(f"{label}: already holding {held}")
            if _stacked_on(obj, support):
                raise _Infeasible(f"{label}: {obj} is under another object")
            info = infos[obj]
            if not planar and not info.disk and min(info.half[:2]) * 2 > PANDA_OPENING - 0.005:
                raise _Infeasible(f"{label}: {obj} is {200 * min(info.half[:2]):.1f} cm wide; "
                                  f"the gripper opens {100 * PANDA_OPENING:.0f} cm")
            k = motion(i, "carry" if held else "free", held, held_grip, {obj})
            last_contact = frozenset({support.get(obj)} - {None})
            steps.append(Step(i, op.name, kind, obj, held_before=held, held_after=obj,
                              grasp_step=i, keyframes=(k,)))
            held, held_grip = obj, i
            if planar:
                grip_params.append(i)
            support[obj] = None
        elif kind == "place":
            if held != obj:
                raise _Infeasible(f"{label}: {obj} is not held"
                                  + (f" (holding {held})" if held else ""))
            target = on
            if target in regions:
                body = regions[target].on
            elif target in infos and target != obj:
                body = target
                if _holds_up(obj, target, support):
                    raise _Infeasible(f"{label}: {target} rests on {obj}")
            else:
                raise _Infeasible(f"{label}: the scene has no region or body {target!r}")
            z = rest_z[body] + infos[body].half[2] + infos[obj].half[2]
            if planar and abs(z - rest_z[obj]) > 0.005:
                raise _Infeasible(f"{label}: the planar robot cannot lift {obj} onto {body} "
                                  f"({100 * (z - rest_z[obj]):+.1f} cm)")
            k = motion(i, "carry", obj, held_grip, {body})
            last_contact = frozenset({obj})
            steps.append(Step(i, op.name, kind, obj, target, body, obj, None, held_grip, (k,),
                              z))
            rest_z[obj] = z
            support[obj] = body
            held, held_grip = None, None
        elif kind == "push":
            if held is not None:
                raise _Infeasible(f"{label}: cannot push while holding {held}")
            if to is None or to not in regions:
                raise _Infeasible(f"{label}: the scene has no region {to!r}")
            below = support.get(obj)
            if below is None or below != regions[to].on:
                raise _Infeasible(f"{label}: {obj} rests on {below}, region {to} is on "
                                  f"{regions[to].on}: a push slides on one support")
            if _stacked_on(obj, support):
                raise _Infeasible(f"{label}: {obj} is under another object")
            k0 = motion(i, "free", None, None, {obj})
            last_contact = frozenset({below})
            k1 = motion(i, "push", obj, i, set(), {below})
            last_contact = frozenset({obj})
            grip_params.append(i)
            steps.append(Step(i, op.name, kind, obj, to, below, None, None, i, (k0, k1),
                              rest_z[obj]))
        elif kind == "move":
            if to is not None and to not in regions and to not in infos:
                raise _Infeasible(f"{label}: the scene has no region or body {to!r}")
            k = motion(i, "carry" if held else "free", held, held_grip, set())
            last_contact = frozenset()
            steps.append(Step(i, op.name, kind, None, to, None, held, held, held_grip, (k,)))
        else:
            raise _Infeasible(f"{label}: unknown mode {kind!r}")
    return tuple(steps), tuple(motions), tuple(grip_params)


def _stacked_on(obj: str, support: dict) -> set[str]:
    """Objects resting (directly) on obj."""
    return {o for o, s in support.items() if s == obj}


def _holds_up(obj: str, target: str, support: dict) -> bool:
    """target rests (directly or not) on obj."""
    seen = set()
    cur = support.get(target)
    while cur is not None and cur not in seen:
        if cur == obj:
            return True
        seen.add(cur)
        cur = support.get(cur)
    return False


# ---------------------------------------------------------------- variable layout


@dataclass(frozen=True)
class Layout:
    """Where each block of variables sits in the NLP's x (pack/unpack)."""

    blocks: tuple[tuple[str, int], ...]  # (name, size) in order

    @property
    def size(self) -> int:
        return sum(s for _, s in self.blocks)

    def slices(self) -> dict[str, slice]:
        out, at = {}, 0
        for name, size in self.blocks:
            out[name] = slice(at, at + size)
            at += size
        return out

    def pack(self, values: dict[str, np.ndarray]) -> np.ndarray:
        return np.concatenate([np.asarray(values[name], dtype=float).reshape(size)
                               for name, size in self.blocks]) if self.blocks else np.zeros(0)

    def unpack(self, x: np.ndarray) -> dict[str, np.ndarray]:
        x = np.asarray(x, dtype=float)
        if x.shape != (self.size,):
            raise ValueError(f"expected {self.size} values, got shape {x.shape}")
        return {name: x[s] for name, s in self.slices().items()}
