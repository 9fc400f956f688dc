"""Lowering: a skeleton (sequence of ground actions) -> TrajectoryProblem.

Each action's mode kind (optimize/kinds) turns it into a step and its motion
phases (see skeleton.py for the phases; docs/formats.md, "solution.json", for what they become). A skeleton that cannot be lowered
(placing what is not held, a region the scene lacks) gives a problem with
`error` set: the solver returns it as infeasible (`proved`), never raises.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

from tampcli.optimize.bodies import body_info, start_support
from tampcli.optimize.hand import open_hand
from tampcli.optimize.kinds import KINDS, SYMBOLIC
from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.skeleton import (
    ImpossibleAction,
    Lowering,
    LoweringError,
    MotionPhase,
    Step,
)


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
    error: str | None = None  # the skeleton cannot be lowered (infeasible)
    error_proved: bool = True  # ... and that is a proof (not a mesh's bounding box's)
    # The action the lowering stopped at (its index): what makes it fail comes from it
    # and the actions before it alone, so a proof holds for every skeleton starting so.
    error_at: int | None = None
    # (action schema, object, role or None) of an ImpossibleAction: the error holds for
    # every skeleton
    impossible: tuple | None = None
    grip_params: tuple[int, ...] = ()  # steps with one continuous grip parameter, in order
    checker: object = field(default=None, repr=False)  # geometry.collision.CollisionChecker
    # optimize.hand.Hand: the fingers' opening throughout (`checker` holds them there);
    # open as lowered, narrowed to the grips chosen (hand.with_hand)
    hand: object = field(default=None, repr=False)
    # World measurements kept per skeleton: world_state.reach_of's ball under "reach"
    # (hand.hand_for's are kept in World.measures, for every skeleton)
    memo: dict = field(default_factory=dict, repr=False)

    @property
    def n(self) -> int:
        return self.world.n

    @property
    def n_keyframes(self) -> int:
        return len(self.motions)

    def at_margin(self, margin: float) -> TrajectoryProblem:
        """This problem with the optimizer's margin `margin` (the tight retries)."""
        return dataclasses.replace(self, options=dataclasses.replace(self.options,
                                                                     margin=margin))

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
    lo = Lowering(infos, supports, {r.name: r for r in scene.regions}, planar, domain,
                  None if planar else world.gripper_opening)
    i = 0
    try:
        for i, op in enumerate(skeleton):
            mode = mode_of(modes, op.action)
            kind = SYMBOLIC if mode is None else KINDS.get(mode.kind)
            if kind is None:
                raise LoweringError(f"{op.name}: unknown mode {mode.kind!r}")
            lo.steps.append(kind.lower(lo, i, op, mode))
    except LoweringError as err:
        impossible = (err.action, err.obj, err.role) if isinstance(err, ImpossibleAction) \
            else None
        return TrajectoryProblem(steps=(), motions=(), error=str(err), impossible=impossible,
                                 error_proved=err.proved, error_at=i, hand=open_hand(world),
                                 **base)
    return TrajectoryProblem(steps=tuple(lo.steps), motions=tuple(lo.motions),
                             grip_params=tuple(lo.grip_params), hand=open_hand(world), **base)


def mode_of(modes, action: str):
    """The action's Mode, None when it has none (a symbolic action)."""
    if modes is None:
        return None
    getter = getattr(modes, "get", None)
    return getter(action) if getter else None
