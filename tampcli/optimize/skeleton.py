"""A skeleton resolved against the scene: its steps, its motion phases, and the
walk that builds them (each mode kind's `lower` adds its own).

Phases (docs/formats.md, "solution.json"): before each grasp, place or push a motion phase
of T waypoints is inserted (free, or carrying what is held); a push then
spans its own pushing motion; a move *is* a motion phase; mode switches and
symbolic actions are instantaneous. Each motion phase ends at a keyframe
(its last waypoint), so keyframes and motion phases are one-to-one.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from tampcli.optimize.bodies import REST_TOLERANCE, face_misfit, region_misfit

if TYPE_CHECKING:
    from tampcli.optimize.kinds.base import ModeKind


@dataclass(frozen=True)
class Step:
    """One action of the skeleton, resolved against the scene."""

    index: int
    name: str  # "(pick a table)"
    kind: ModeKind  # what the action's mode means, through every stage
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
    kind: str  # "free", "carry", or a kind's own motion (a push's pushing)
    enter_contact: frozenset[str] = frozenset()  # bodies allowed to touch in the last segment
    leave_contact: frozenset[str] = frozenset()  # ... in the first segment
    sliding: frozenset[str] = frozenset()  # bodies `attached` slides on (push; planar carry)
    own: bool = False  # the action itself (a move, a push's pushing), not the way to it
    pushes: bool = False  # the tool pushes `attached` along its support: taken where the
    # motion starts (not at a mode switch), kept upright at its resting height


class LoweringError(Exception):
    """The skeleton cannot be lowered: infeasible, proved unless `proved` is False (a
    test on a mesh's bounding box); never raised out of `lower`."""

    def __init__(self, message: str, proved: bool = True):
        super().__init__(message)
        self.proved = proved


class ImpossibleAction(LoweringError):
    """No skeleton can do `action` to `obj` (with `role` = (mode role, value), e.g.
    ("on", "goal"), when given), whatever its other arguments and whatever comes
    before: no grasp of the object fits the gripper; its footprint fits the region in
    no orientation. Every such ground action is infeasible, proved."""

    def __init__(self, message: str, action: str, obj: str,
                 role: tuple[str, str] | None = None):
        super().__init__(message)
        self.action, self.obj, self.role = action, obj, role


class Lowering:
    """The walk over a skeleton that lowering is: what is held, what rests where."""

    def __init__(self, infos: dict, supports: dict, regions: dict, planar: bool, domain,
                 gripper_opening: float | None = None):
        self.infos = infos
        self.gripper_opening = gripper_opening  # World.gripper_opening: None, no width limit
        self.regions = regions
        self.planar = planar
        self.domain = domain
        self.steps: list[Step] = []
        self.motions: list[MotionPhase] = []
        self.grip_params: list[int] = []
        self.held: str | None = None
        self.held_grip: int | None = None
        self.support = dict(supports)  # body under each movable object, as the skeleton goes
        self.rest_z = {n: info.pose[2] for n, info in infos.items()}
        self.last_contact: frozenset[str] = frozenset()  # bodies touched at the last keyframe

    def motion(self, step_index: int, kind: str, attached, grip, enter, sliding=(),
               own: bool = False, pushes: bool = False) -> int:
        """Append a motion phase; returns its keyframe index."""
        if self.planar and kind == "carry":
            # The planar robot cannot lift: what it carries slides over every
            # surface at the height of its bottom (across tables that touch).
            bottom = self.rest_z[attached] - self.infos[attached].half[2]
            sliding = {n for n, b in self.infos.items()
                       if n != attached and abs(b.top - bottom) <= REST_TOLERANCE}
        m = MotionPhase(len(self.motions), step_index, attached, grip, kind, frozenset(enter),
                        self.last_contact, frozenset(sliding) - {None}, own, pushes)
        self.motions.append(m)
        return m.index

    def roles(self, op, mode) -> tuple[str | None, str | None, str | None]:
        """(object, on, to) of the action: its mode's roles bound to its arguments."""
        return tuple(self._resolve(getattr(mode, role, None), op, mode)
                     for role in ("object", "on", "to"))

    def fits(self, label: str, op, obj: str, region: str, role: str) -> None:
        """Raise where obj's footprint fits `region` in no orientation: ImpossibleAction
        (every such action, in any skeleton) for a box, cylinder or sphere; unproved
        for a mesh's or URDF's bounding box."""
        why = region_misfit(obj, self.infos[obj], self.regions[region])
        if why and not self.infos[obj].exact:
            raise LoweringError(f"{label}: {why} (as its bounding box)", proved=False)
        if why:
            raise ImpossibleAction(f"{label}: {why}", op.action, obj, (role, region))

    def fits_on(self, label: str, op, obj: str, body: str, overhang: float) -> None:
        """Raise where obj's footprint lies on `body`'s top face in no orientation (as
        `fits` does; unproved where either is a mesh's or URDF's bounding box)."""
        why = face_misfit(obj, self.infos[obj], self.infos[body], overhang)
        if why and not (self.infos[obj].exact and self.infos[body].exact):
            raise LoweringError(f"{label}: {why} (as a bounding box)", proved=False)
        if why:
            raise ImpossibleAction(f"{label}: {why}", op.action, obj, ("on", body))

    def movable(self, label: str, obj: str | None) -> None:
        if obj is None or obj not in self.infos:
            raise LoweringError(f"{label}: the scene has no object {obj!r}")
        if self.infos[obj].fixed:
            raise LoweringError(f"{label}: {obj} is fixed")

    def stacked_on(self, obj: str) -> set[str]:
        """Objects resting (directly) on obj."""
        return {o for o, s in self.support.items() if s == obj}

    def holds_up(self, obj: str, target: str) -> bool:
        """target rests (directly or not) on obj."""
        seen = set()
        cur = self.support.get(target)
        while cur is not None and cur not in seen:
            if cur == obj:
                return True
            seen.add(cur)
            cur = self.support.get(cur)
        return False

    def _resolve(self, value: str | None, op, mode) -> str | None:
        if value is None:
            return None
        if not value.startswith("?"):
            return value.lower()
        params = getattr(mode, "params", None)
        domain = self.domain
        if params is None and domain is not None and domain.action(op.action) is not None:
            params = tuple(p.name for p in domain.action(op.action).params)
        if params is None:
            raise LoweringError(f"{op.name}: cannot resolve {value} without the action's "
                                "parameters")
        params = tuple(getattr(p, "name", p) for p in params)
        if value not in params:
            raise LoweringError(f"{op.name}: the action has no parameter {value}")
        return str(op.args[params.index(value)]).lower()
