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

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize.kinds import KINDS
from tampcli.render.physics_values import (
    OVERLAP_NOTED,
    Grip,
    ObjectDrift,
    Overlap,
    PhaseDrift,
    PhysicsReplay,
    PhysicsSettings,
    Touch,
    object_mass,
)
from tampcli.render.replay import Replay, phase_label
from tampcli.solution_fit import finger_rows

TOUCH_EVERY = 8  # simulation steps between looks at what the robot touches (30 Hz)


def replay_physics(inputs, mode_kind=None, speed: float | None = None,
                   settings: PhysicsSettings | None = None) -> PhysicsReplay:
    """Simulate `inputs` (render.inputs.RenderInputs) and compare with the plan.

    The timing is the replay's default (or `speed`), not the video's: planners
    assume quasi-static motion, and a 1-second video of a long push would fling
    the object.
    """
    from tampcli.geometry.world import World

    settings = settings or PhysicsSettings()
    with World(inputs.scene, visuals=False) as world:
        replay = Replay(inputs.solution, world.tool_pose, mode_kind=mode_kind, speed=speed,
                        pause=settings.pause,
                        fingers=None if inputs.file is None else finger_rows(inputs.file, world))
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
        world.set_state(np.asarray(first.q), first.poses, fingers_closed=False,
                        fingers=first.fingers)
        self.gripping = False  # the fingers closed on what is held (not the file's values)
        self.sim.set_contacts(settings.friction, settings.restitution,
                              settings.spinning_friction, settings.rolling_friction)
        self.masses = {name: object_mass(inputs.scene.body(name), settings.density)
                       for name in first.poses if inputs.scene.body(name).shape != "urdf"}
        self.sim.make_dynamic(self.masses)
        # A turn about its own upright axis leaves a cylinder as it was, and any turn a
        # sphere: not drift (the planner lets either turn while pushed).
        self.symmetry = {name: {"cylinder": "axis", "sphere": "full"}.get(
            inputs.scene.body(name).shape) for name in first.poses}
        self.steps = 0
        self.tracking = 0.0
        self.phase_drifts: dict[str, list[PhaseDrift]] = {name: [] for name in first.poses}
        self.grips: list[Grip] = []
        # [name, phase, depth, contact or None until the grasp that ends an approach]
        self.overlaps: list[list] = []
        self.contact: dict[str, float] = {}  # depth at the last release, during the retreat
        self.touches: dict[tuple[str, int], tuple[str, float]] = {}  # first per phase

    def _step(self, q, track: bool = True, fingers=None) -> None:
        """One step towards q; `fingers`: the solution's finger values there (the
        fingers follow them unless closed on what is held)."""
        if fingers is not None and not self.gripping:
            self.sim.open_fingers(fingers)
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
        settings = self.settings
        for _ in range(int(round(settings.arrive_seconds * settings.hz))):
            if np.max(np.abs(self.sim.joint_positions() - q)) < settings.arrive_tolerance \
                    and np.max(np.abs(self.sim.joint_velocities())) < settings.arrive_speed:
                return
            self._step(q, track=False)

    def _switch(self, held: str | None, index: int, grip: bool) -> None:
        """Let go of what is held, then take `held` (fingers closing on it when `grip`),
        at waypoint `index`."""
        q = self.replay.q[index]
        self._arrive(q)
        released = self.sim.held
        if released is not None:
            # the retreat's first move may still pass into it (play's exemptions)
            self.sim.release(heed=False)
            self.contact[released] = self.sim.overlap(released)
            # Opened as far as the solution opens them after the release (fully when
            # it does not say): a hand opened wide among packed neighbours hits them.
            after = self.replay.fingers_at(min(index + 1, len(self.replay.q) - 1))
            self.sim.open_fingers(after)
            self.gripping = False
            self._wait(q, self.settings.settle_after_place)
        if held is not None:
            self._taking(held)
            if grip and self.sim.close_fingers_on(held):
                self.gripping = True
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
                        # At the item's first waypoint, not its first mid-step sample: a
                        # grasp switches on the carry's first segment, and half a step
                        # along it the tool is 0.7-1.3 mm and 0.4 deg from where the plan
                        # grasps (blind8 p06, p07), a grip error every place inherits.
                        self._switch(holding[j][0], item.index, holding[j][1])
                    if j in exempt:
                        self.sim.ignore_robot(exempt[j])
                self._step(state.q, fingers=state.fingers)
                if j in exempt and s % 4 == 0:
                    self._note_overlap(exempt[j], item.phase)
                if s % TOUCH_EVERY == 0:
                    self._note_touches(exempt.get(j), item.phase)
            if j in exempt and exempt.get(j + 1) != exempt[j] and exempt[j] != self.sim.held:
                self.sim.heed_robot(exempt[j])
                self.contact.pop(exempt[j], None)
            last_of_phase = j + 1 == len(items) or items[j + 1].phase != item.phase
            if last_of_phase and 0 <= item.phase < len(self.solution.phases):
                self._record(item.phase)
        final = self.replay.state_at(self.replay.duration)
        if self.sim.held is not None:
            released = self.sim.held
            self._switch(None, len(self.replay.q) - 1, False)
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

    def _note_touches(self, allowed: str | None, k: int) -> None:
        """The first touch in phase k of each object the plan keeps clear of the robot
        (all but the one held and the one it may pass into here)."""
        if not 0 <= k < len(self.solution.phases):
            return
        for name in self.phase_drifts:
            if name in (self.sim.held, allowed) or (name, k) in self.touches:
                continue
            links = self.sim.touching(name)
            if links:
                self.touches[(name, k)] = (links[0], self.steps / self.settings.hz)

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
            distance, angle = _drift(planned, self.sim.pose_of(name), self.symmetry.get(name))
            self.phase_drifts[name].append(PhaseDrift(k, self._label(k), distance, angle))

    def report(self) -> PhysicsReplay:
        final = self.replay.state_at(self.replay.duration)
        objects = []
        for name, planned in final.poses.items():
            simulated = self.sim.pose_of(name)
            distance, angle = _drift(planned, simulated, self.symmetry.get(name))
            objects.append(ObjectDrift(
                name, self.masses.get(name, 0.0), distance, angle,
                tuple(transforms.xyzquat_from_pose(planned)),
                tuple(transforms.xyzquat_from_pose(simulated)),
                tuple(self.phase_drifts.get(name, ()))))
        hz = self.settings.hz
        touches = tuple(Touch(name, link, k, self._label(k), seconds)
                        for (name, k), (link, seconds) in self.touches.items())
        return PhysicsReplay(self.steps / hz, self.steps, hz, tuple(objects), self.tracking,
                             tuple(self.grips), self._overlaps(),
                             tuple(sorted(touches, key=lambda t: t.seconds)))

    def _overlaps(self) -> tuple[Overlap, ...]:
        return tuple(Overlap(name, k, self._label(k), depth, contact or 0.0)
                     for name, k, depth, contact in self.overlaps)


def _drift(planned: np.ndarray, simulated: np.ndarray,
           symmetry: str | None = None) -> tuple[float, float]:
    """(position drift in m, rotation drift in degrees). `symmetry`: "axis" (a cylinder:
    only the turn of its own z axis counts), "full" (a sphere: no turn counts) or None."""
    if symmetry == "full":
        angle = 0.0
    elif symmetry == "axis":
        c = float(np.clip(planned[:3, 2] @ simulated[:3, 2], -1.0, 1.0))
        angle = math.acos(c)
    else:
        rot = planned[:3, :3].T @ simulated[:3, :3]
        angle = float(np.linalg.norm(transforms.rotation_log(rot)))
    return float(np.linalg.norm(simulated[:3, 3] - planned[:3, 3])), math.degrees(angle)
