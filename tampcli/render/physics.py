"""`--physics`: replay a solution with PyBullet dynamics and measure how far the
objects end up from where the plan put them.

The robot's joints track the replay's timeline under position control; a
carried object hangs from the tool by a fixed constraint (collisions between
it and the robot are off meanwhile, as the planner assumes); pushed objects
are moved by contact alone; gravity acts throughout. A large drift means the
plan relies on something physics does not grant: an unstable placement, a
push that slips, a motion too fast to track.

Works on a World of its own through its public handles (`pb`, `client`,
`robot_id`, `pb_body`), so no geometry code changes for it.
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.geometry import transforms
from tampcli.render.replay import Replay

HZ = 240.0  # PyBullet's default step
SETTLE_SECONDS = 1.0  # after the last waypoint, let things come to rest
OBJECT_MASS = 0.1  # kg: light enough for any arm to carry
JOINT_FORCE = {"planar": 50.0}  # N for the planar robot's prismatic joints
JOINT_FORCE_OTHER = 200.0  # N m: stronger than gravity on a Panda's links
FINGER_FORCE = 20.0


def replay_physics(inputs, mode_kind=None, speed: float | None = None, hz: float = HZ,
                   settle: float = SETTLE_SECONDS) -> dict:
    """Simulate and compare; returns per-object drift and the robot's tracking error.

    The timing is the replay's default (or `speed`), not the video's: planners
    assume quasi-static motion, and a 1-second video of a long push would fling
    the object.
    """
    from tampcli.geometry.world import World

    with World(inputs.scene) as world:
        replay = Replay(inputs.solution, world.tool_pose, mode_kind=mode_kind, speed=speed,
                        pause=0.25)
        sim = _Simulation(world, inputs.solution.robot.get("model"))
        first = replay.state_at(0.0)
        world.set_state(np.asarray(first.q), first.poses, fingers_closed=False)
        sim.make_dynamic(first.poses)
        steps = 0
        tracking = 0.0
        n = int(math.ceil(replay.duration * hz))
        for i in range(n + int(settle * hz)):
            state = replay.state_at(min(i / hz, replay.duration))
            sim.hold(state.held)
            sim.drive(state.q)
            sim.pb.stepSimulation(physicsClientId=sim.client)
            steps += 1
            if i % 8 == 0:
                tracking = max(tracking, sim.tracking_error(state.q))
        final = replay.state_at(replay.duration)
        objects = {}
        for name, planned in final.poses.items():
            simulated = sim.pose_of(name)
            rot = planned[:3, :3].T @ simulated[:3, :3]
            angle = float(np.linalg.norm(transforms.rotation_log(rot)))
            objects[name] = {
                "distance": float(np.linalg.norm(simulated[:3, 3] - planned[:3, 3])),
                "angle_deg": math.degrees(angle),
                "planned": transforms.xyzquat_from_pose(planned),
                "simulated": transforms.xyzquat_from_pose(simulated),
            }
    return {"seconds": steps / hz, "steps": steps, "hz": hz, "objects": objects,
            "max_distance": max((o["distance"] for o in objects.values()), default=0.0),
            "tracking_error": tracking}


class _Simulation:
    """Dynamics on top of one World (which it borrows)."""

    def __init__(self, world, model: str | None):
        self.world, self.pb, self.client = world, world.pb, world.client
        self.robot = world.robot_id
        pb, c = self.pb, self.client
        by_name, links, movable = {}, {}, []
        for j in range(pb.getNumJoints(self.robot, physicsClientId=c)):
            info = pb.getJointInfo(self.robot, j, physicsClientId=c)
            by_name[info[1].decode()] = j
            links[info[12].decode()] = j
            if info[2] != pb.JOINT_FIXED:
                movable.append(j)
        if all(name in by_name for name in world.joint_names):
            self.joints = [by_name[name] for name in world.joint_names]
        else:  # a robot built in code (planar) names its joints only in the World
            self.joints = movable[:world.n]
        self.tool = links.get(world.tool_link, self.joints[-1])
        self.fingers = list(getattr(world, "finger_joints", ()))
        self.force = JOINT_FORCE.get(model, JOINT_FORCE_OTHER)
        self.links = [-1, *range(pb.getNumJoints(self.robot, physicsClientId=c))]
        self.held: str | None = None
        self.constraint: int | None = None
        pb.setGravity(0.0, 0.0, -9.81, physicsClientId=c)
        pb.setTimeStep(1.0 / HZ, physicsClientId=c)

    def make_dynamic(self, poses: dict) -> None:
        for name in poses:
            self.pb.changeDynamics(self.world.pb_body(name), -1, mass=OBJECT_MASS,
                                   lateralFriction=0.6, physicsClientId=self.client)

    def drive(self, q) -> None:
        pb, c = self.pb, self.client
        n = len(self.joints)
        pb.setJointMotorControlArray(self.robot, self.joints, pb.POSITION_CONTROL,
                                     targetPositions=list(q), forces=[self.force] * n,
                                     physicsClientId=c)
        if self.fingers:  # open: the constraint holds the object, not friction
            pb.setJointMotorControlArray(self.robot, self.fingers, pb.POSITION_CONTROL,
                                         targetPositions=[0.04] * len(self.fingers),
                                         forces=[FINGER_FORCE] * len(self.fingers),
                                         physicsClientId=c)

    def hold(self, name: str | None) -> None:
        """Attach `name` to the tool where it is now (or release what is held)."""
        if name == self.held:
            return
        pb, c = self.pb, self.client
        if self.constraint is not None:
            pb.removeConstraint(self.constraint, physicsClientId=c)
            self._collide(self.held, True)
            self.constraint = None
        self.held = name
        if name is None:
            return
        body = self.world.pb_body(name)
        link_pos, link_orn = pb.getLinkState(self.robot, self.tool, computeForwardKinematics=True,
                                             physicsClientId=c)[:2]
        obj_pos, obj_orn = pb.getBasePositionAndOrientation(body, physicsClientId=c)
        inv_pos, inv_orn = pb.invertTransform(link_pos, link_orn)
        rel_pos, rel_orn = pb.multiplyTransforms(inv_pos, inv_orn, obj_pos, obj_orn)
        self.constraint = pb.createConstraint(
            self.robot, self.tool, body, -1, pb.JOINT_FIXED, [0, 0, 0], rel_pos, [0, 0, 0],
            rel_orn, [0, 0, 0, 1], physicsClientId=c)
        pb.changeConstraint(self.constraint, maxForce=500.0, physicsClientId=c)
        self._collide(name, False)

    def _collide(self, name: str | None, enable: bool) -> None:
        if name is None:
            return
        body = self.world.pb_body(name)
        for link in self.links:
            self.pb.setCollisionFilterPair(self.robot, body, link, -1, int(enable),
                                           physicsClientId=self.client)

    def tracking_error(self, q) -> float:
        states = self.pb.getJointStates(self.robot, self.joints, physicsClientId=self.client)
        return float(np.max(np.abs(np.array([s[0] for s in states]) - np.asarray(q))))

    def pose_of(self, name: str) -> np.ndarray:
        pos, orn = self.pb.getBasePositionAndOrientation(self.world.pb_body(name),
                                                         physicsClientId=self.client)
        return transforms.pose(transforms.quat_to_matrix(orn), pos)
