"""World: the scene loaded in one PyBullet client (DIRECT), and the robot's kinematics.

PyBullet stays behind this class: it owns its client, closes it, and no
query leaves the simulator changed. Kinematic queries (fk, Jacobians, ik)
run on a numpy copy of the joint tree (chain.py) and never touch PyBullet;
only `set_state` (for replay), `add_visual_box` (scenery) and
`start_dynamics` (the physics replay) change the simulator.
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.arms import PANDA
from tampcli.geometry.chain import REVOLUTE
from tampcli.geometry.ik import IkMemo
from tampcli.geometry.scene import Scene
from tampcli.geometry.scene_check import entry_error
from tampcli.geometry.shapes import Shape
from tampcli.geometry.world import _measure
from tampcli.geometry.world._arm import FingerJoints, closing_fraction, load_arm, tool_frame
from tampcli.geometry.world._dynamics import Dynamics
from tampcli.geometry.world._gripper import GripperQueries
from tampcli.geometry.world._load import load_body, make_planar
from tampcli.geometry.world._pybullet import pybullet

PANDA_FINGERS = PANDA.fingers.joints
PLANAR_LINKS = ("planar_x", "planar_body")


class World(GripperQueries):
    """A scene in PyBullet; use as a context manager or call `close()`.

    Robots: an arm (a built-in one of geometry/arms.py, e.g. the Panda with
    tool frame `panda_grasptarget`, 0.105 m beyond the hand along its z axis;
    or the scene's URDF), fixed base at `base`, q = its arm joints, its
    fingers not in q and open for kinematics and collisions; or `planar` (a
    vertical cylinder whose joints `x`, `y` hold world coordinates, bounded
    by the scene's extent). Link frames are URDF link frames; a tool offset
    adds a link of its own (`tool_link` names it). All bodies are static in
    the simulator: nothing is simulated unless `start_dynamics` is called.
    `visuals` False: without the shapes only images need (a Panda loads in 0.01 s, not 0.17).
    """

    def __init__(self, scene: Scene, visuals: bool = True):
        self.scene = scene
        self.visuals = visuals
        self._ik = IkMemo()
        # Measurements of this robot that depend on nothing else, kept by whoever makes
        # them for the next skeleton (optimize/hand.py: the hand's opening per width).
        self.measures: dict = {}
        self._pb = pybullet
        self._client = pybullet.connect(pybullet.DIRECT)
        try:
            self._bodies: dict[str, int] = {}
            for body in scene.bodies:
                self._bodies[body.name] = load_body(self._pb, self._client, scene, body, visuals)
            self._load_robot()
        except BaseException:
            self.close()
            raise

    # ------------------------------------------------------------ lifecycle

    def close(self) -> None:
        if self._client is not None and self._client >= 0:
            if self._pb.isConnected(physicsClientId=self._client):
                self._pb.disconnect(physicsClientId=self._client)
        self._client = None

    def __enter__(self) -> World:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:  # noqa: BLE001 - interpreter shutdown: nothing left to release
            pass

    # ------------------------------------------------------------ loading

    def _load_robot(self) -> None:
        pb, c, spec = self._pb, self._client, self.scene.robot
        base = spec.base_pose
        self._fingers: FingerJoints | None = None
        arm = spec.arm
        link_names = None
        if arm is None:  # planar
            uid = make_planar(pb, c, spec.radius, spec.height, float(base[2, 3]))
            joints: tuple[str, ...] = ("x", "y")
            pb_joints: tuple[int, ...] = (0, 1)
            link_names = {-1: "planar_base", 0: PLANAR_LINKS[0], 1: PLANAR_LINKS[1]}
        else:
            loaded = load_arm(pb, c, self.scene, arm, self.visuals)
            uid, joints, self._fingers = loaded.uid, loaded.joints, loaded.fingers
            by_name = {pb.getJointInfo(uid, j, physicsClientId=c)[1].decode(): j
                       for j in range(pb.getNumJoints(uid, physicsClientId=c))}
            pb_joints = tuple(by_name[j] for j in joints)
        self._robot = uid
        self.joint_names: tuple[str, ...] = tuple(joints)
        self._pb_joints = pb_joints
        fixed_values = {}
        if self._fingers is not None:
            fixed_values = dict(zip(self._fingers.pb, self._fingers.open, strict=True))
            self._set_fingers(self._fingers.open)
        chain = _measure.measure_chain(pb, c, uid, _pb_names_to_q(pb, c, uid, pb_joints),
                                       fixed_values, link_names)
        self._tool_pb_link = "planar_body" if arm is None else arm.tool_link
        self.chain, self.tool_link = tool_frame(self.scene, chain, arm, PLANAR_LINKS[1])
        self.link_names: tuple[str, ...] = self.chain.names
        self._tool_index = self.chain.index[self.tool_link]
        self._virtual_tool = len(self.chain.links) > len(chain.links)
        lower, upper = [], []
        for j in self._pb_joints:
            info = pb.getJointInfo(uid, j, physicsClientId=c)
            lo, hi = info[8], info[9]
            if info[2] == REVOLUTE and hi < lo:  # continuous joint
                lo, hi = -math.pi, math.pi
            lower.append(lo)
            upper.append(hi)
        if arm is None:
            lo, hi = self._scene_extent()
            lower, upper = list(lo[:2]), list(hi[:2])
        self.lower = np.array(lower, dtype=float)
        self.upper = np.array(upper, dtype=float)
        if spec.start is not None:
            if len(spec.start) != len(joints):
                raise entry_error(self.scene, f"expected {len(joints)} joint values (for "
                                  f"{', '.join(joints)}), got {len(spec.start)}", "robot", 0,
                                  "start")
            start = np.array(spec.start, dtype=float)
        elif arm is None:
            start = base[:2, 3].copy()
        elif arm.ready is not None:
            start = np.array(arm.ready, dtype=float)
        else:
            start = np.clip(np.zeros(len(joints)), self.lower, self.upper)
        self.start = start
        for v in (self.lower, self.upper, self.start):
            v.flags.writeable = False
        self._set_joints(self.start)
        self._gripper = _measure.gripper_size(pb, c, uid, self._fingers, self.chain,
                                              self._tool_index, self.start)

    def _scene_extent(self) -> tuple[np.ndarray, np.ndarray]:
        """Box around all bodies (x, y, z); a unit box about the base when the scene is empty."""
        boxes = [self._aabb(uid) for uid in self._bodies.values()]
        if not boxes:
            base = self.scene.robot.base_pose[:3, 3]
            return base - 1.0, base + 1.0
        return np.min([lo for lo, _ in boxes], axis=0), np.max([hi for _, hi in boxes], axis=0)

    def aabb(self, name: str, base_only: bool = False) -> tuple[np.ndarray, np.ndarray]:
        """Axis-aligned box (lo, hi) of a scene body (its base link only, or all its
        links) where it stands now: its start pose unless `set_state` moved it."""
        links = [-1] if base_only else None
        return _measure.aabb(self._pb, self._client, self._bodies[name], links)

    def _aabb(self, uid: int) -> tuple[np.ndarray, np.ndarray]:
        return _measure.aabb(self._pb, self._client, uid)

    # ------------------------------------------------------------ kinematics

    @property
    def n(self) -> int:
        return len(self.joint_names)

    @property
    def body_names(self) -> tuple[str, ...]:
        return tuple(b.name for b in self.scene.bodies)

    @property
    def movable_names(self) -> tuple[str, ...]:
        return tuple(b.name for b in self.scene.bodies if not b.fixed)

    def fk(self, q) -> dict[str, np.ndarray]:
        """World 4x4 frame of every robot link (URDF link frames)."""
        return dict(zip(self.link_names, self.chain.fk_list(q), strict=True))

    def tool_pose(self, q) -> np.ndarray:
        return self.chain.fk_list(q)[self._tool_index]

    def tool_poses(self, qs) -> np.ndarray:
        """(T, 4, 4) tool poses for the rows of qs (batched: cheap per waypoint)."""
        return self.chain.fk_batch(qs)[:, self._tool_index]

    def tool_jacobians(self, qs) -> np.ndarray:
        """(T, 6, n) tool Jacobians (linear; angular) for the rows of qs."""
        return self.chain.tool_jacobian_batch(self.chain.fk_batch(qs), self._tool_index)

    def point_jacobian(self, q, link: str, point_world) -> np.ndarray:
        """(3, n): d point / d q for a point rigidly attached to `link`."""
        frames = self.chain.fk_list(q)
        return self.chain.jacobian_from_frames(frames, self.chain.index[link], point_world)

    def tool_jacobian(self, q) -> np.ndarray:
        """(6, n): linear velocity of the tool origin; angular velocity of the tool."""
        frames = self.chain.fk_list(q)
        i = self._tool_index
        return np.vstack([self.chain.jacobian_from_frames(frames, i, frames[i][:3, 3]),
                          self.chain.angular_jacobian_from_frames(frames, i)])

    def ik(self, target, seed=None, position_only: bool = False, iterations: int = 200,
           restarts: int = 8, tolerance: float = 1e-5, rng_seed: int = 0):
        """Joint values that put the tool at `target` (4x4): returns (q, residual).

        Damped least squares from `seed`, the start configuration, then random seeds,
        within the joint limits. `residual`: the norm of [position error (m),
        orientation error (rad)] (position only when `position_only`); the caller
        judges it. A question asked before gets the same answer (ik.IkMemo)."""
        return self._ik.ask(self, np.asarray(target, dtype=float), seed, position_only,
                            iterations, restarts, tolerance, rng_seed)

    def ik_many(self, targets, seeds, rng_seeds, restarts: int = 8, tolerance: float = 1e-5):
        """[`ik` of each (target, seed, rng_seed)], first seeds batched (IkMemo.ask_many)."""
        return self._ik.ask_many(self, targets, seeds, rng_seeds, False, 200, restarts, tolerance)

    def body_pose(self, name: str) -> np.ndarray:
        """Start pose (4x4) of a scene body."""
        return self.scene.body(name).matrix

    def base_link(self) -> str:
        return self.link_names[0]

    # ------------------------------------------------------------ replay

    def _set_joints(self, q) -> None:
        for j, v in zip(self._pb_joints, q, strict=True):
            self._pb.resetJointState(self._robot, j, float(v), physicsClientId=self._client)

    def _set_fingers(self, values) -> None:
        for j, v in zip(self._fingers.pb, values, strict=True):
            self._pb.resetJointState(self._robot, j, float(v), physicsClientId=self._client)

    def set_state(self, q, body_poses: dict | None = None, fingers_closed: bool = False,
                  finger_opening: float | None = None, fingers=None) -> None:
        """Move the robot and bodies in the simulator (for replay only).

        Fingers: `fingers`, each finger joint's value, when given (a solution
        file's finger columns); else open; or closed, to `finger_opening` (the
        value of every finger joint named in the scene) when given, else until
        they touch a movable body between them (fully closed when none is).
        """
        self._set_joints(np.asarray(q, dtype=float))
        for name, t in (body_poses or {}).items():
            t = np.asarray(t, dtype=float)
            if t.shape == (7,):
                t = transforms.pose_from_xyzquat(t)
            self._pb.resetBasePositionAndOrientation(
                self._bodies[name], t[:3, 3], transforms.matrix_to_quat(t[:3, :3]),
                physicsClientId=self._client)
        if self._fingers is None:
            return
        if fingers is not None:
            self._set_fingers(tuple(float(v) for v in fingers))
            return
        self._set_fingers(self._fingers.open)
        if not fingers_closed:
            return
        if finger_opening is not None:
            # Joints that mimic a finger follow it: the same fraction of their travel.
            (open_, closed) = self._fingers.open[0], self._fingers.closed[0]
            self._set_fingers(self._fingers.at((float(finger_opening) - open_) / (closed - open_)))
            return
        closing_fraction(self._pb, self._client, self._robot, self._fingers,
                         self._between_fingers())

    def _between_fingers(self) -> list[int]:
        """Movable bodies whose boxes meet the open fingers' box."""
        lo, hi = _measure.aabb(self._pb, self._client, self._robot, self._fingers.links)
        found = []
        for name in self.movable_names:
            uid = self._bodies[name]
            b_lo, b_hi = self._aabb(uid)
            if np.all(b_lo <= hi) and np.all(lo <= b_hi):
                found.append(uid)
        return found

    def camera_image(self, width: int, height: int, eye, target, up=(0.0, 0.0, 1.0),
                     fov: float = 50.0) -> np.ndarray:
        """(height, width, 3) uint8 RGB image of the current state (TinyRenderer)."""
        pb, c = self._pb, self._client
        view = pb.computeViewMatrix(list(eye), list(target), list(up), physicsClientId=c)
        proj = pb.computeProjectionMatrixFOV(fov, width / height, 0.01, 20.0, physicsClientId=c)
        _, _, rgba, _, _ = pb.getCameraImage(width, height, view, proj,
                                             renderer=pb.ER_TINY_RENDERER, physicsClientId=c)
        image = np.asarray(rgba, dtype=np.uint8).reshape(height, width, 4)
        return np.ascontiguousarray(image[:, :, :3])

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """(lo, hi) corners of a box around the scene and the robot as it stands now."""
        los, his = [], []
        for uid in [*self._bodies.values(), self._robot]:
            lo, hi = self._aabb(uid)
            los.append(lo)
            his.append(hi)
        return np.min(los, axis=0), np.max(his, axis=0)

    def part_boxes(self) -> list[tuple[np.ndarray, np.ndarray]]:
        """(lo, hi) of the base link of every scene body, then of every robot link,
        as they stand now: what a camera framing the scene must keep in view."""
        pb, c = self._pb, self._client
        robot_links = range(-1, pb.getNumJoints(self._robot, physicsClientId=c))
        return ([_measure.aabb(pb, c, self._bodies[name], [-1]) for name in self.body_names]
                + [_measure.aabb(pb, c, self._robot, [link]) for link in robot_links])

    def add_visual_box(self, center, half_extents, color) -> None:
        """Draw a box that has no collision shape, so it can never change a collision
        query or `bounds()` (video scenery: goal regions)."""
        pb, c = self._pb, self._client
        visual = pb.createVisualShape(pb.GEOM_BOX, halfExtents=list(half_extents),
                                      rgbaColor=list(color), physicsClientId=c)
        pb.createMultiBody(0.0, -1, visual, list(center), physicsClientId=c)

    def start_dynamics(self, hz: float, gravity: float = -9.81) -> Dynamics:
        """Turn this World into a simulation stepping at `hz` under `gravity` (m/s^2, z).

        For a World of its own: the bodies made dynamic move for good.
        """
        fingers = self._fingers
        return Dynamics(self._pb, self._client, self._robot, dict(self._bodies),
                        self.joint_names, self._tool_pb_link, fingers.pb if fingers else (),
                        fingers.open if fingers else (), hz, gravity)

    # ------------------------------------------------------------ collision shapes

    def robot_link_shapes(self, link: int) -> list[Shape]:
        """Collision shapes of robot link `link` (index in `chain.links`), in its frame."""
        if link == self._tool_index and self._virtual_tool:
            return []  # the tool frame is an offset, no link of the URDF
        return _measure.link_shapes(self._pb, self._client, self._robot,
                                    self.chain.links[link].pb_index)

    def body_collision_shapes(self, name: str) -> list[Shape]:
        """Collision shapes of all links of a URDF scene body, in the body's frame."""
        return _measure.body_shapes(self._pb, self._client, self._bodies[name],
                                    self.scene.body(name).matrix)


def _pb_names_to_q(pb, client, uid, pb_joints) -> dict[str, int]:
    names = {}
    for i, j in enumerate(pb_joints):
        names[pb.getJointInfo(uid, j, physicsClientId=client)[1].decode()] = i
    return names

