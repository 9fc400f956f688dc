"""Dynamics on a World's client: gravity, contact parameters, joint motors, a grasp.

The one place where the simulator is allowed to change for good: a World
that starts dynamics is no longer a static copy of its scene (bodies gain
mass, the robot is driven), so it is meant for a World of its own.
"""

from __future__ import annotations

import numpy as np

from tampcli.geometry import transforms

CLEAR = 1e-3  # m: a released body collides with the robot again once this far from it


class Dynamics:
    """The robot driven under position control; named bodies free to move.

    A grasp is a fixed constraint between the tool and the body, with the
    fingers (if any) closed until they touch it; the held body and the robot
    do not collide meanwhile, as the planner assumes. A released body keeps
    ignoring the robot until it is `CLEAR` of every link, so fingers that
    open around it, or a palm the plan let overlap it, do not knock it away.
    """

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
        self._finger_open = [float(v) for v in finger_open]  # one per finger joint
        self._finger_target = list(self._finger_open)
        self._sliding = [pb.getJointInfo(robot, j, physicsClientId=c)[2] == pb.JOINT_PRISMATIC
                         for j in self._fingers]
        self._links = [-1, *range(pb.getNumJoints(robot, physicsClientId=c))]
        base = pb.getBodyInfo(robot, physicsClientId=c)[0].decode()
        self._link_names = {-1: base or "base", **{j: name for name, j in links.items()}}
        self._held: str | None = None
        self._constraint: int | None = None
        self._released: set[str] = set()
        pb.setGravity(0.0, 0.0, gravity, physicsClientId=c)
        pb.setTimeStep(1.0 / hz, physicsClientId=c)

    def set_contacts(self, friction: float, restitution: float, spinning: float,
                     rolling: float) -> None:
        """The same contact parameters on every body and robot link (Bullet multiplies
        the two sides' frictions and restitutions at a contact)."""
        pb, c = self._pb, self._client
        parts = [(uid, -1) for uid in self._bodies.values()]
        parts += [(self._robot, link) for link in self._links]
        for uid, link in parts:
            pb.changeDynamics(uid, link, lateralFriction=friction, restitution=restitution,
                              spinningFriction=spinning, rollingFriction=rolling,
                              physicsClientId=c)

    def make_dynamic(self, masses: dict[str, float]) -> None:
        """Give each named body its mass (kg): from now on it falls and gets pushed."""
        for name, mass in masses.items():
            self._pb.changeDynamics(self._bodies[name], -1, mass=float(mass),
                                    physicsClientId=self._client)

    def drive(self, q, force: float, finger_force: float, gain: float = 0.1) -> None:
        """Motor targets: the arm's joints to `q` (position `gain`: PyBullet's own default
        is 0.1), the fingers to where the grasp wants them."""
        pb, c = self._pb, self._client
        n = len(self._joints)
        pb.setJointMotorControlArray(self._robot, self._joints, pb.POSITION_CONTROL,
                                     targetPositions=list(q), forces=[force] * n,
                                     positionGains=[gain] * n, physicsClientId=c)
        if self._fingers:
            k = len(self._fingers)
            pb.setJointMotorControlArray(self._robot, self._fingers, pb.POSITION_CONTROL,
                                         targetPositions=self._finger_target,
                                         forces=[finger_force] * k, physicsClientId=c)

    def close_fingers_on(self, name: str) -> list[float]:
        """Finger targets that just touch `name`: each sliding finger's position less
        its distance to the body (not 0: a finger driven into the held body would
        fight the grasp). A hinged finger (a URDF gripper's) stays where it is: the
        grasp's constraint holds the body. Returns the targets (one per finger)."""
        pb, c = self._pb, self._client
        body = self._bodies[name]
        targets = []
        for j, opening, sliding in zip(self._fingers, self._finger_open, self._sliding,
                                       strict=True):
            position = pb.getJointState(self._robot, j, physicsClientId=c)[0]
            if not sliding:
                targets.append(float(position))
                continue
            points = pb.getClosestPoints(self._robot, body, 2 * opening, linkIndexA=j,
                                         physicsClientId=c)
            gap = min((p[8] for p in points), default=0.0)
            targets.append(float(np.clip(position - gap, 0.0, opening)))
        self._finger_target = targets
        return targets

    def ignore_robot(self, name: str) -> None:
        """`name` and the robot stop colliding until `heed_robot` (or a grasp and
        release) hands it back."""
        self._released.discard(name)
        self._collide(name, False)

    def heed_robot(self, name: str) -> None:
        """`name` collides with the robot again as soon as it is clear of it."""
        self._released.add(name)

    def open_fingers(self, values=None) -> None:
        """Drive the fingers open, or to `values` (one per finger joint: a hand
        opened only so far, as a solution's finger columns give it)."""
        if values is None:
            self._finger_target = list(self._finger_open)
            return
        if len(values) != len(self._fingers):
            raise ValueError(f"{len(values)} finger values for {len(self._fingers)} joints")
        self._finger_target = [float(v) for v in values]

    def grasp(self, name: str, max_force: float) -> None:
        """Attach `name` to the tool where both are now; it ignores the robot meanwhile."""
        pb, c = self._pb, self._client
        self.release()
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
        self._released.discard(name)
        self._collide(name, False)
        self._held = name

    def release(self, heed: bool = True) -> None:
        """Let go of the held body (if any); it collides with the robot again once clear
        (with `heed`), else once `heed_robot` says so."""
        if self._constraint is not None:
            self._pb.removeConstraint(self._constraint, physicsClientId=self._client)
            self._constraint = None
        if self._held is not None and heed:
            self._released.add(self._held)
        self._held = None

    @property
    def held(self) -> str | None:
        return self._held

    def _collide(self, name: str, enable: bool) -> None:
        body = self._bodies[name]
        for link in self._links:
            self._pb.setCollisionFilterPair(self._robot, body, link, -1, int(enable),
                                            physicsClientId=self._client)

    def _restore_collisions(self) -> None:
        pb, c = self._pb, self._client
        for name in sorted(self._released):
            points = pb.getClosestPoints(self._robot, self._bodies[name], CLEAR,
                                         physicsClientId=c)
            if not points:
                self._collide(name, True)
                self._released.discard(name)

    def overlap(self, name: str) -> float:
        """How deep (m, 0 when apart) the robot reaches into `name` now, collisions
        between them on or off."""
        points = self._pb.getClosestPoints(self._robot, self._bodies[name], 0.0,
                                           physicsClientId=self._client)
        return max([0.0, *(-p[8] for p in points)])

    def touching(self, name: str) -> tuple[str, ...]:
        """The robot's links in contact with body `name` after the last step (none while
        their collisions are off: held, or just released)."""
        points = self._pb.getContactPoints(self._robot, self._bodies[name],
                                           physicsClientId=self._client)
        return tuple(dict.fromkeys(self._link_names.get(p[3], str(p[3])) for p in points))

    def step(self) -> None:
        self._restore_collisions()
        self._pb.stepSimulation(physicsClientId=self._client)

    def joint_positions(self) -> np.ndarray:
        """The driven joints' values now, in q order."""
        states = self._pb.getJointStates(self._robot, self._joints, physicsClientId=self._client)
        return np.array([s[0] for s in states])

    def joint_velocities(self) -> np.ndarray:
        """The driven joints' velocities now (rad/s, or m/s for a sliding joint), in q order."""
        states = self._pb.getJointStates(self._robot, self._joints, physicsClientId=self._client)
        return np.array([s[1] for s in states])

    def finger_positions(self) -> np.ndarray:
        """The finger joints' values now (m each; empty without fingers)."""
        if not self._fingers:
            return np.zeros(0)
        states = self._pb.getJointStates(self._robot, self._fingers,
                                         physicsClientId=self._client)
        return np.array([s[0] for s in states])

    def pose_of(self, name: str) -> np.ndarray:
        """A body's simulated pose now (4x4)."""
        pos, orn = self._pb.getBasePositionAndOrientation(self._bodies[name],
                                                          physicsClientId=self._client)
        return transforms.pose(transforms.quat_to_matrix(orn), pos)
