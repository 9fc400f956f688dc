"""What the physics replay measures and how a verdict is drawn from it: settings,
per-object and per-phase drift, grips, overlaps, the violations, masses
(render/physics.py runs the replay)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tampcli.geometry.shapes import mesh_hulls

OVERLAP_NOTED = 0.001  # m: a deeper pass of the robot into an exempt object is reported


@dataclass(frozen=True)
class PhysicsSettings:
    """The replay's physical constants (SI units); docs/physics.md explains each."""

    hz: float = 240.0  # PyBullet's default step
    density: float = 500.0  # kg/m^3, for an object whose scene entry gives no `mass`
    friction: float = 0.8  # lateral, on every body and link (a contact gets 0.8 * 0.8)
    restitution: float = 0.0  # nothing bounces
    spinning_friction: float = 0.001
    # Rolling resistance, on every body and link. Bullet gives a contact r_a f_b + r_b f_a
    # (1.6 x this) as a lever arm: a resisting torque of lever x normal force, 0.1 mm
    # here, the least of the engineering tables (hardened steel balls on steel; wood,
    # plastic and rubber roll 0.5-2 mm and more). At 0 a ball set down at 0.2 mm/s rolls
    # on for good (blind9 p08); at 0.1 mm a 2.6 cm ball at 1 cm/s stops within 2 mm.
    rolling_friction: float = 6.25e-5
    arm_force: float = 200.0  # N m: stronger than gravity on a Panda's links
    planar_force: float = 50.0  # N for the planar robot's prismatic joints
    # Position gain of the joint motors: PyBullet's 0.1 lags a Panda 0.03 rad behind
    # the replay's speed, enough to drag a carried object across a support's edge.
    gain: float = 0.3
    finger_force: float = 20.0  # N: fingers touch the held object, they do not crush it
    grasp_force: float = 500.0  # N: the most the grasp constraint pulls the held object with
    # rad (m): the robot is at rest at a grasp or place within it. At 1e-3 a Panda's
    # tool stood 0.4-0.6 mm off at each, as much as a tight pack's gaps leave (blind8
    # p06: 1 mm); at 2e-4, 0.1 mm, reached within 0.1 s more per replay.
    arrive_tolerance: float = 2e-4
    arrive_speed: float = 1e-3  # rad/s (m/s): and still, every joint slower than this
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
class Touch:
    """A robot link touching an object where the plan has it clear (not held, not the
    object taken or let go of in the move next to it): the first such touch of each
    object in a phase."""

    name: str
    link: str
    phase: int
    label: str
    seconds: float  # simulated, from the replay's start


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
    touches: tuple[Touch, ...] = ()  # in order

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
                             for o in self.overlaps],
                "touches": [{"object": t.name, "link": t.link, "phase": t.phase,
                             "label": t.label, "seconds": t.seconds} for t in self.touches]}


@dataclass(frozen=True)
class DriftViolation:
    """An object that ended farther from its planned pose than a tolerance allows."""

    drift: ObjectDrift
    first: PhaseDrift | None  # the phase it first exceeded it at; None: in the final settle
    max_distance: float
    max_angle_deg: float
    touch: Touch | None = None  # the robot's last touch of it up to that phase

    def describe(self) -> str:
        d = self.drift
        where = (f"first beyond at the end of phase {self.first.phase}: {self.first.label}"
                 if self.first is not None else "first beyond after the last phase, while "
                 "everything settled")
        struck = "" if self.touch is None else (
            f"; touched by {self.touch.link} in phase {self.touch.phase}: {self.touch.label} "
            f"({self.touch.seconds:.2f} s into the replay), where the plan keeps it clear")
        return (f"physics: {d.name} ends {d.distance:.3f} m and {d.angle_deg:.1f} deg from "
                f"its planned pose (tolerance {self.max_distance:g} m, "
                f"{self.max_angle_deg:g} deg); {where}{struck}")


def drift_violations(replay: PhysicsReplay, max_distance: float,
                     max_angle_deg: float) -> tuple[DriftViolation, ...]:
    """The objects whose final pose is beyond either tolerance, in scene order."""
    out = []
    for o in replay.objects:
        if o.distance <= max_distance and o.angle_deg <= max_angle_deg:
            continue
        first = o.first_beyond(max_distance, max_angle_deg)
        touches = [t for t in replay.touches if t.name == o.name
                   and (first is None or t.phase <= first.phase)]
        out.append(DriftViolation(o, first, max_distance, max_angle_deg,
                                  touches[-1] if touches else None))
    return tuple(out)


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
