"""The physics replay: a solution replayed with PyBullet dynamics, and how far the
objects end up from where the plan put them. `render --physics` shows it,
`validate --physics` judges by it (`drift_violations`, `overlap_violations`);
both run this one replay.

What is simulated (docs/physics.md states the numbers): the robot's joints
track the replay's timeline under position control; at a grasp the robot
first comes to rest, the fingers close until they touch the object, and a
fixed constraint ties it to the tool; at a place the robot comes to rest,
lets go, opens its fingers and waits `settle_after_place` seconds while the
object settles. A pushed object is tied to the pusher as the planner moves it;
gravity acts throughout; objects weigh their volume times a uniform density
unless the scene gives their `mass`. Where the planner lets the robot touch
the object it takes or lets go of, the replay lets it pass and measures how
deep. A large drift means the plan relies on something physics does not
grant: an unstable placement, a carried object that scrapes another, a motion
too fast to track.

Works on a World of its own, through the Dynamics it starts: the forces and
masses are this module's, the simulator stays the World's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.shapes import mesh_hulls
from tampcli.optimize.kinds import KINDS
from tampcli.render.replay import Replay, phase_label

OVERLAP_NOTED = 0.001  # m: a deeper pass of the robot into an exempt object is reported


@dataclass(frozen=True)
class PhysicsSettings:
    """The replay's physical constants (SI units); docs/physics.md explains each."""

    hz: float = 240.0  # PyBullet's default step
    density: float = 500.0  # kg/m^3, for an object whose scene entry gives no `mass`
    friction: float = 0.8  # lateral, on every body and link (a contact gets 0.8 * 0.8)
    restitution: float = 0.0  # nothing bounces
    spinning_friction: float = 0.001
    rolling_friction: float = 0.0
    arm_force: float = 200.0  # N m: stronger than gravity on a Panda's links
    planar_force: float = 50.0  # N for the planar robot's prismatic joints
    # Position gain of the joint motors: PyBullet's 0.1 lags a Panda 0.03 rad behind
    # the replay's speed, enough to drag a carried object across a support's edge.
    gain: float = 0.3
    finger_force: float = 20.0  # N: fingers touch the held object, they do not crush it
    grasp_force: float = 500.0  # N: the most the grasp constraint pulls the held object with
    arrive_tolerance: float = 1e-3  # rad (m): the robot is at rest at a grasp or place within it
    arrive_seconds: float = 1.0  # the most the robot is given to come to rest there
    grip_seconds: float = 0.25  # fingers closing before the grasp takes hold
    settle_after_place: float = 0.5  # seconds the robot waits after letting go
    settle_final: float = 1.0  # seconds after the last waypoint
    pause: float = 0.25  # seconds the timeline holds at each instantaneous action


@dataclass(frozen=True)
class PhaseDrift:
    """An object's drift from its planned pose at the end of phase `phase`."""

    phase: int  # index into the solution's phases
    label: str  # the phase's caption (replay.phase_label)
    distance: float  # m
    angle_deg: float


@dataclass(frozen=True)
class ObjectDrift:
    """Where one object ended up, against the plan."""

    name: str
    mass: float  # kg, as simulated
    distance: float  # m, final position drift
    angle_deg: float  # final rotation drift
    planned: tuple[float, ...]  # xyz + quat
    simulated: tuple[float, ...]
    phases: tuple[PhaseDrift, ...] = ()  # at each phase end where it was not held

    def first_beyond(self, max_distance: float, max_angle_deg: float) -> PhaseDrift | None:
        """The first phase at whose end the drift exceeded either tolerance."""
        for drift in self.phases:
            if drift.distance > max_distance or drift.angle_deg > max_angle_deg:
                return drift
        return None


@dataclass(frozen=True)
class Grip:
    """A grasp as simulated: the object and the gap the closed fingers left (m)."""

    name: str
    opening: float


@dataclass(frozen=True)
class Overlap:
    """The robot passing into an object where the planner allows it (and the replay
    lets it through): the last move before taking it, the first after letting go."""

    name: str
    phase: int
    label: str
    depth: float  # m, the deepest seen in this phase
    contact: float  # m, how deep the robot was into it where it took or let go of it

    def describe(self, max_distance: float) -> str:
        return (f"physics: the robot passes {self.depth * 1000:.1f} mm into {self.name} in "
                f"phase {self.phase}: {self.label}, {(self.depth - self.contact) * 1000:.1f} "
                "mm deeper than where it takes or lets go of it; the replay lets it through, "
                f"a real robot would shove it farther than the {max_distance:g} m allowed")


@dataclass(frozen=True)
class PhysicsReplay:
    """The outcome of one physics replay."""

    seconds: float  # simulated
    steps: int
    hz: float
    objects: tuple[ObjectDrift, ...]
    tracking_error: float  # largest joint error seen while moving (rad, or m for planar)
    grips: tuple[Grip, ...] = ()  # each finger grasp, in order
    overlaps: tuple[Overlap, ...] = ()  # deeper than OVERLAP_NOTED, in order

    @property
    def max_distance(self) -> float:
        return max((o.distance for o in self.objects), default=0.0)

    def as_json(self) -> dict:
        return {"seconds": self.seconds, "steps": self.steps, "hz": self.hz,
                "objects": {o.name: {"distance": o.distance, "angle_deg": o.angle_deg,
                                     "mass": o.mass, "planned": list(o.planned),
                                     "simulated": list(o.simulated),
                                     "phases": [{"phase": d.phase, "label": d.label,
                                                 "distance": d.distance,
                                                 "angle_deg": d.angle_deg}
                                                for d in o.phases]}
                            for o in self.objects},
                "max_distance": self.max_distance, "tracking_error": self.tracking_error,
                "grips": [{"object": g.name, "opening": g.opening} for g in self.grips],
                "overlaps": [{"object": o.name, "phase": o.phase, "label": o.label,
                              "depth": o.depth, "contact": o.contact}
                             for o in self.overlaps]}


@dataclass(frozen=True)
class DriftViolation:
    """An object that ended farther from its planned pose than a tolerance allows."""

    drift: ObjectDrift
    first: PhaseDrift | None  # the phase it first exceeded it at; None: in the final settle
    max_distance: float
    max_angle_deg: float

    def describe(self) -> str:
        d = self.drift
        where = (f"first beyond at the end of phase {self.first.phase}: {self.first.label}"
                 if self.first is not None else "first beyond after the last phase, while "
                 "everything settled")
        return (f"physics: {d.name} ends {d.distance:.3f} m and {d.angle_deg:.1f} deg from "
                f"its planned pose (tolerance {self.max_distance:g} m, "
                f"{self.max_angle_deg:g} deg); {where}")


def drift_violations(replay: PhysicsReplay, max_distance: float,
                     max_angle_deg: float) -> tuple[DriftViolation, ...]:
    """The objects whose final pose is beyond either tolerance, in scene order."""
    return tuple(DriftViolation(o, o.first_beyond(max_distance, max_angle_deg), max_distance,
                                max_angle_deg)
                 for o in replay.objects
                 if o.distance > max_distance or o.angle_deg > max_angle_deg)


def overlap_violations(replay: PhysicsReplay, max_distance: float) -> tuple[Overlap, ...]:
    """The robot's passes into an object more than `max_distance` deeper than its contact
    where it takes or lets go of it: the replay lets them through, a real robot would
    shove the object at least that far."""
    return tuple(o for o in replay.overlaps if o.depth - o.contact > max_distance)


def object_mass(body, density: float) -> float:
    """The scene's `mass`, else the body's volume times `density` (kg)."""
    if body.mass is not None:
        return float(body.mass)
    if body.shape == "box":
        volume = float(np.prod(body.size))
    elif body.shape == "cylinder":
        r, h = body.size
        volume = math.pi * r * r * h
    elif body.shape == "sphere":
        volume = 4.0 / 3.0 * math.pi * body.size[0] ** 3
    else:  # a mesh: its convex parts, as the collision checker sees it
        from scipy.spatial import ConvexHull

        volume = sum(ConvexHull(part.vertices).volume
                     for part in mesh_hulls(body.mesh, body.scale))
    return volume * density


def replay_physics(inputs, mode_kind=None, speed: float | None = None,
                   settings: PhysicsSettings | None = None) -> PhysicsReplay:
    """Simulate `inputs` (render.inputs.RenderInputs) and compare with the plan.

    The timing is the replay's default (or `speed`), not the video's: planners
    assume quasi-static motion, and a 1-second video of a long push would fling
    the object.
    """
    from tampcli.geometry.world import World

    settings = settings or PhysicsSettings()
    with World(inputs.scene) as world:
        replay = Replay(inputs.solution, world.tool_pose, mode_kind=mode_kind, speed=speed,
                        pause=settings.pause)
        run = _Run(world, replay, inputs, settings, mode_kind or (lambda action: None))
        run.play()
        return run.report()


class _Run:
    """One replay's simulation state: the clock, the tracking error, phase drifts."""

    def __init__(self, world, replay: Replay, inputs, settings: PhysicsSettings, mode_kind):
        self.replay, self.settings, self.mode_kind = replay, settings, mode_kind
        self.solution = inputs.solution
        model = inputs.solution.robot.get("model")
        self.force = settings.planar_force if model == "planar" else settings.arm_force
        self.sim = world.start_dynamics(settings.hz)
        first = replay.state_at(0.0)
        world.set_state(np.asarray(first.q), first.poses, fingers_closed=False)
        self.sim.set_contacts(settings.friction, settings.restitution,
                              settings.spinning_friction, settings.rolling_friction)
        self.masses = {name: object_mass(inputs.scene.body(name), settings.density)
                       for name in first.poses if inputs.scene.body(name).shape != "urdf"}
        self.sim.make_dynamic(self.masses)
        self.steps = 0
        self.tracking = 0.0
        self.phase_drifts: dict[str, list[PhaseDrift]] = {name: [] for name in first.poses}
        self.grips: list[Grip] = []
        # [name, phase, depth, contact or None until the grasp that ends an approach]
        self.overlaps: list[list] = []
        self.contact: dict[str, float] = {}  # depth at the last release, during the retreat

    def _step(self, q, track: bool = True) -> None:
        self.sim.drive(q, self.force, self.settings.finger_force, self.settings.gain)
        self.sim.step()
        self.steps += 1
        if track and self.steps % 8 == 0:
            error = float(np.max(np.abs(self.sim.joint_positions() - np.asarray(q))))
            self.tracking = max(self.tracking, error)

    def _wait(self, q, seconds: float) -> None:
        for _ in range(int(round(seconds * self.settings.hz))):
            self._step(q, track=False)

    def _arrive(self, q) -> None:
        """Hold still at q until the joints are there (grasps and places happen at rest)."""
        q = np.asarray(q)
        for _ in range(int(round(self.settings.arrive_seconds * self.settings.hz))):
            if np.max(np.abs(self.sim.joint_positions() - q)) < self.settings.arrive_tolerance:
                return
            self._step(q, track=False)

    def _switch(self, held: str | None, q, grip: bool) -> None:
        """Let go of what is held, then take `held` (fingers closing on it when `grip`)."""
        self._arrive(q)
        released = self.sim.held
        if released is not None:
            # the retreat's first move may still pass into it (play's exemptions)
            self.sim.release(heed=False)
            self.contact[released] = self.sim.overlap(released)
            self.sim.open_fingers()
            self._wait(q, self.settings.settle_after_place)
        if held is not None:
            self._taking(held)
            if grip and self.sim.close_fingers_on(held):
                self._wait(q, self.settings.grip_seconds)
                self.grips.append(Grip(held, float(np.sum(self.sim.finger_positions()))))
            self.sim.grasp(held, self.settings.grasp_force)

    def _kind(self, action: str):
        """The action's mode kind (optimize.kinds), or None when unknown."""
        name = self.mode_kind(action)
        return KINDS.get(name) if name is not None else None

    def _holding(self, items, ends) -> list[tuple[str | None, bool]]:
        """Per timeline item: the object tied to the tool, and whether the fingers grip
        it. A push ties its object too: the planner moves it with the pusher, sliding
        on its surface, and does not model how a point contact would turn it."""
        out = []
        for item, end in zip(items, ends, strict=True):
            state = self.replay.state_at(end - 0.5 * item.duration)
            phase = self.solution.phases[item.phase] \
                if 0 <= item.phase < len(self.solution.phases) else None
            kind = self._kind(phase.action) if phase is not None and phase.action else None
            pushing = item.moving and phase.attached is not None and kind is not None \
                and not kind.holds
            out.append((phase.attached, False) if pushing else (state.held, True))
        return out

    def _exempt(self, items, holding) -> dict[int, str]:
        """Item index -> the object the robot may pass into there, as the planner lets
        it (optimize/path.py's allowed contacts): the one it takes, in the last move
        before taking it; the one it let go, until the end of the first move after."""
        marks: dict[int, str] = {}
        for j in range(1, len(items)):
            before, after = holding[j - 1][0], holding[j][0]
            if after is not None and after != before:
                i = j - 1
                while i >= 0 and not items[i].moving:
                    marks[i] = after
                    i -= 1
                if i >= 0:
                    marks[i] = after
            if before is not None and after != before:
                i = j
                while i < len(items) and not items[i].moving and holding[i][0] is None:
                    marks[i] = before
                    i += 1
                if i < len(items) and holding[i][0] is None:
                    marks[i] = before
        return marks

    def play(self) -> None:
        hz = self.settings.hz
        items = self.replay.items
        ends = np.cumsum([item.duration for item in items])
        holding = self._holding(items, ends)
        exempt = self._exempt(items, holding)
        for j, item in enumerate(items):
            start = ends[j] - item.duration
            n = max(1, int(math.ceil(item.duration * hz)))
            for s in range(n):
                # mid-step samples stay inside this item of the timeline
                state = self.replay.state_at(start + item.duration * (s + 0.5) / n)
                if s == 0:
                    if holding[j][0] != self.sim.held:
                        self._switch(holding[j][0], state.q, holding[j][1])
                    if j in exempt:
                        self.sim.ignore_robot(exempt[j])
                self._step(state.q)
                if j in exempt and s % 4 == 0:
                    self._note_overlap(exempt[j], item.phase)
            if j in exempt and exempt.get(j + 1) != exempt[j] and exempt[j] != self.sim.held:
                self.sim.heed_robot(exempt[j])
                self.contact.pop(exempt[j], None)
            last_of_phase = j + 1 == len(items) or items[j + 1].phase != item.phase
            if last_of_phase and 0 <= item.phase < len(self.solution.phases):
                self._record(item.phase)
        final = self.replay.state_at(self.replay.duration)
        if self.sim.held is not None:
            released = self.sim.held
            self._switch(None, final.q, False)
            self.sim.heed_robot(released)
        self._wait(final.q, self.settings.settle_final)

    def _note_overlap(self, name: str, k: int) -> None:
        depth = self.sim.overlap(name)
        if depth <= OVERLAP_NOTED or name == self.sim.held \
                or not 0 <= k < len(self.solution.phases):
            return
        last = self.overlaps[-1] if self.overlaps else None
        if last is not None and last[:2] == [name, k]:
            last[2] = max(last[2], depth)
        else:
            self.overlaps.append([name, k, depth, self.contact.get(name)])

    def _taking(self, name: str) -> None:
        """The approach to `name` is over: its passes are measured against this contact."""
        depth = self.sim.overlap(name)
        for entry in self.overlaps:
            if entry[0] == name and entry[3] is None:
                entry[3] = depth

    def _label(self, k: int) -> str:
        return phase_label(self.solution.phases[k])

    def _record(self, k: int) -> None:
        for name, poses in self.solution.objects.items():
            if name == self.sim.held or name not in self.phase_drifts:
                continue
            planned = transforms.pose_from_xyzquat(poses[min(k + 1, len(poses) - 1)])
            distance, angle = _drift(planned, self.sim.pose_of(name))
            self.phase_drifts[name].append(PhaseDrift(k, self._label(k), distance, angle))

    def report(self) -> PhysicsReplay:
        final = self.replay.state_at(self.replay.duration)
        objects = []
        for name, planned in final.poses.items():
            simulated = self.sim.pose_of(name)
            distance, angle = _drift(planned, simulated)
            objects.append(ObjectDrift(
                name, self.masses.get(name, 0.0), distance, angle,
                tuple(transforms.xyzquat_from_pose(planned)),
                tuple(transforms.xyzquat_from_pose(simulated)),
                tuple(self.phase_drifts.get(name, ()))))
        hz = self.settings.hz
        return PhysicsReplay(self.steps / hz, self.steps, hz, tuple(objects), self.tracking,
                             tuple(self.grips), self._overlaps())

    def _overlaps(self) -> tuple[Overlap, ...]:
        return tuple(Overlap(name, k, self._label(k), depth, contact or 0.0)
                     for name, k, depth, contact in self.overlaps)


def _drift(planned: np.ndarray, simulated: np.ndarray) -> tuple[float, float]:
    """(position drift in m, rotation drift in degrees)."""
    rot = planned[:3, :3].T @ simulated[:3, :3]
    angle = float(np.linalg.norm(transforms.rotation_log(rot)))
    return float(np.linalg.norm(simulated[:3, 3] - planned[:3, 3])), math.degrees(angle)
