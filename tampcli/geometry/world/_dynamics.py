"""Dynamics on a World's client: gravity, joint motors, a grasp constraint.

The one place where the simulator is allowed to change for good: a World
that starts dynamics is no longer a static copy of its scene (bodies gain
mass, the robot is driven), so it is meant for a World of its own.
"""

from __future__ import annotations

import numpy as np

from tampcli.geometry import transforms


class Dynamics:
    """The robot driven under position control; named bodies free to move."""

    def __init__(self, pb, client: int, robot: int, bodies: dict[str, int],
                 joint_names: tuple[str, ...], tool_link: str, fingers: tuple[int, ...],
                 finger_open: tuple[float, ...], hz: float, gravity: float):
        self._pb, self._client, self._robot, self._bodies = pb, client, robot, bodies
        c = client
        by_name, links, movable = {}, {}, []
        for j in range(pb.getNumJoints(robot, physicsClientId=c)):
            info = pb.getJointInfo(robot, j, physicsClientId=c)
            by_name[info[1].decode()] = j
            links[info[12].decode()] = j
            if info[2] != pb.JOINT_FIXED:
                movable.append(j)
        if all(name in by_name for name in joint_names):
            self._joints = [by_name[name] for name in joint_names]
        else:  # a robot built in code (planar) names its joints only in the World
            self._joints = movable[:len(joint_names)]
        self._tool = links.get(tool_link, self._joints[-1])
        self._fingers = list(fingers)
        self._finger_open = finger_open
        self._links = [-1, *range(pb.getNumJoints(robot, physicsClientId=c))]
        self._held: str | None = None
        self._constraint: int | None = None
        pb.setGravity(0.0, 0.0, gravity, physicsClientId=c)
        pb.setTimeStep(1.0 / hz, physicsClientId=c)

    def make_dynamic(self, names, mass: float, friction: float) -> None:
        """Give the named bodies `mass` (kg) and lateral `friction`: they fall and get pushed."""
        for name in names:
            self._pb.changeDynamics(self._bodies[name], -1, mass=mass, lateralFriction=friction,
                                    physicsClientId=self._client)

    def drive(self, q, force: float, finger_force: float) -> None:
        """Motor targets: the arm's joints to `q`; the fingers (if any) open."""
        pb, c = self._pb, self._client
        n = len(self._joints)
        pb.setJointMotorControlArray(self._robot, self._joints, pb.POSITION_CONTROL,
                                     targetPositions=list(q), forces=[force] * n,
                                     physicsClientId=c)
        if self._fingers:  # open: the constraint holds the object, not friction
            k = len(self._fingers)
            pb.setJointMotorControlArray(self._robot, self._fingers, pb.POSITION_CONTROL,
                                         targetPositions=list(self._finger_open),
                                         forces=[finger_force] * k, physicsClientId=c)

    def hold(self, name: str | None, max_force: float) -> None:
        """Attach `name` to the tool where it is now (or release what is held); the held
        body does not collide with the robot meanwhile, as the planner assumes."""
        if name == self._held:
            return
        pb, c = self._pb, self._client
        if self._constraint is not None:
            pb.removeConstraint(self._constraint, physicsClientId=c)
            self._collide(self._held, True)
            self._constraint = None
        self._held = name
        if name is None:
            return
        body = self._bodies[name]
        link_pos, link_orn = pb.getLinkState(self._robot, self._tool,
                                             computeForwardKinematics=True,
                                             physicsClientId=c)[:2]
        obj_pos, obj_orn = pb.getBasePositionAndOrientation(body, physicsClientId=c)
        inv_pos, inv_orn = pb.invertTransform(link_pos, link_orn)
        rel_pos, rel_orn = pb.multiplyTransforms(inv_pos, inv_orn, obj_pos, obj_orn)
        self._constraint = pb.createConstraint(
            self._robot, self._tool, body, -1, pb.JOINT_FIXED, [0, 0, 0], rel_pos, [0, 0, 0],
            rel_orn, [0, 0, 0, 1], physicsClientId=c)
        pb.changeConstraint(self._constraint, maxForce=max_force, physicsClientId=c)
        self._collide(name, False)

    def _collide(self, name: str | None, enable: bool) -> None:
        if name is None:
            return
        body = self._bodies[name]
        for link in self._links:
            self._pb.setCollisionFilterPair(self._robot, body, link, -1, int(enable),
                                            physicsClientId=self._client)

    def step(self) -> None:
        self._pb.stepSimulation(physicsClientId=self._client)

    def joint_positions(self) -> np.ndarray:
        """The driven joints' values now, in q order."""
        states = self._pb.getJointStates(self._robot, self._joints, physicsClientId=self._client)
        return np.array([s[0] for s in states])

    def pose_of(self, name: str) -> np.ndarray:
        """A body's simulated pose now (4x4)."""
        pos, orn = self._pb.getBasePositionAndOrientation(self._bodies[name],
                                                          physicsClientId=self._client)
        return transforms.pose(transforms.quat_to_matrix(orn), pos)
