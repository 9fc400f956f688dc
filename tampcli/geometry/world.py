"""World: the scene loaded in one PyBullet client (DIRECT), and the robot's kinematics.

PyBullet stays behind this class: it owns its client, closes it, and no
query leaves the simulator changed. Kinematic queries (fk, Jacobians, ik)
run on a numpy copy of the joint tree (chain.py) and never touch PyBullet;
only `set_state` (for replay) moves things.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from tampcli.errors import SceneError
from tampcli.geometry import transforms
from tampcli.geometry.chain import REVOLUTE, Chain, measure_chain
from tampcli.geometry.ik import solve_ik
from tampcli.geometry.scene import PANDA_READY, Body, Scene
from tampcli.geometry.scene_check import body_error, entry_error, urdf_problem
from tampcli.geometry.shapes import mesh_hulls


def _import_pybullet():
    """PyBullet writes "pybullet build time: ..." on the process's stderr (fd 2, from C)
    when imported: keep that line off what users read."""
    import os
    import sys

    sys.stderr.flush()
    try:
        saved = os.dup(2)
    except OSError:  # no fd 2 to silence
        import pybullet as pb
        import pybullet_data as data
        return pb, data
    try:
        quiet = os.open(os.devnull, os.O_WRONLY)
        os.dup2(quiet, 2)
        os.close(quiet)
        import pybullet as pb
        import pybullet_data as data
    finally:
        os.dup2(saved, 2)
        os.close(saved)
    return pb, data


pybullet, pybullet_data = _import_pybullet()

PANDA_URDF = "franka_panda/panda.urdf"
PANDA_JOINTS = tuple(f"panda_joint{i}" for i in range(1, 8))
PANDA_TOOL = "panda_grasptarget"
PANDA_FINGERS = ("panda_finger_joint1", "panda_finger_joint2")
PANDA_FINGER_OPEN = 0.04
PLANAR_LINKS = ("planar_x", "planar_body")


class World:
    """A scene in PyBullet; use as a context manager or call `close()`.

    Robots: `panda` (pybullet_data's Franka Panda, fixed base at `base`; q =
    the 7 arm joints; tool frame `panda_grasptarget`, 0.105 m beyond the hand
    along its z axis; the fingers are not in q and stay open for kinematics
    and collisions); `planar` (a vertical cylinder whose joints `x`, `y` hold
    world coordinates, bounded by the scene's extent); or any URDF arm with
    the `joints` and `tool_link` the scene names. Link frames are URDF link
    frames. All bodies are static in the simulator: nothing is simulated.
    """

    def __init__(self, scene: Scene):
        self.scene = scene
        self.pb = pybullet
        self.client = pybullet.connect(pybullet.DIRECT)
        try:
            self._bodies: dict[str, int] = {}
            for body in scene.bodies:
                self._bodies[body.name] = self._load_body(body)
            self._load_robot()
        except BaseException:
            self.close()
            raise

    # ------------------------------------------------------------ lifecycle

    def close(self) -> None:
        if self.client is not None and self.client >= 0:
            if self.pb.isConnected(physicsClientId=self.client):
                self.pb.disconnect(physicsClientId=self.client)
        self.client = None

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

    def _load_body(self, body: Body) -> int:
        pb, c = self.pb, self.client
        pos, orn = body.pose[:3], body.pose[3:]
        if body.shape == "urdf":
            uid = self._load_urdf(body.urdf, pos, orn, body.scale[0],
                                  lambda message: body_error(self.scene, body, "urdf", message))
            pb.changeVisualShape(uid, -1, rgbaColor=body.color, physicsClientId=c)
            return uid
        if body.shape == "box":
            half = [s / 2 for s in body.size]
            col = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=half, physicsClientId=c)
            vis = pb.createVisualShape(pb.GEOM_BOX, halfExtents=half, rgbaColor=body.color,
                                       physicsClientId=c)
        elif body.shape == "cylinder":
            r, h = body.size
            col = pb.createCollisionShape(pb.GEOM_CYLINDER, radius=r, height=h, physicsClientId=c)
            vis = pb.createVisualShape(pb.GEOM_CYLINDER, radius=r, length=h,
                                       rgbaColor=body.color, physicsClientId=c)
        elif body.shape == "sphere":
            col = pb.createCollisionShape(pb.GEOM_SPHERE, radius=body.size[0], physicsClientId=c)
            vis = pb.createVisualShape(pb.GEOM_SPHERE, radius=body.size[0],
                                       rgbaColor=body.color, physicsClientId=c)
        else:
            col, vis = self._load_mesh(body)
        return pb.createMultiBody(0.0, col, vis, pos, orn, physicsClientId=c)

    def _load_mesh(self, body: Body) -> tuple[int, int]:
        """Collision and visual shapes of a mesh body; a file either reader refuses is a
        SceneError at the body's `mesh` key.

        The file is read (and its hulls built, cached for the collision checker)
        before PyBullet sees it: that names what is wrong, where PyBullet only
        says that it failed.
        """
        pb, c = self.pb, self.client
        try:
            mesh_hulls(body.mesh, body.scale)
        except SceneError as e:
            raise body_error(self.scene, body, "mesh", f"{e.location()}: {e.message}") from None
        try:
            col = pb.createCollisionShape(pb.GEOM_MESH, fileName=body.mesh,
                                          meshScale=list(body.scale), physicsClientId=c)
            vis = pb.createVisualShape(pb.GEOM_MESH, fileName=body.mesh,
                                       meshScale=list(body.scale), rgbaColor=body.color,
                                       physicsClientId=c)
        except pb.error:
            col = -1
        if col < 0:
            hint = " (an OBJ file needs `v` and `f` lines)" if body.mesh.lower().endswith(
                ".obj") else ""
            raise body_error(self.scene, body, "mesh",
                             f"PyBullet cannot read the mesh {body.mesh}{hint}")
        return col, vis

    def _load_urdf(self, path, pos, orn, scale: float, error) -> int:
        """loadURDF; `error(message)` makes the located SceneError for a file it refuses."""
        problem = urdf_problem(path)
        if problem:
            raise error(problem)
        try:
            return self.pb.loadURDF(path, pos, orn, useFixedBase=True, globalScaling=scale,
                                    physicsClientId=self.client)
        except self.pb.error as e:
            reason = str(e).rstrip(".")
            raise error(f"PyBullet cannot load {path}: {reason} (a malformed link, or a mesh "
                        "file it names is missing)") from None

    def _load_robot(self) -> None:
        pb, c, spec = self.pb, self.client, self.scene.robot
        base = spec.base_pose
        self.finger_joints: tuple[int, ...] = ()
        link_names = None
        if spec.model == "planar":
            uid = self._make_planar(spec.radius, spec.height, float(base[2, 3]))
            joints = ("x", "y")
            tool = "planar_body"
            pb_joint_names = {0: "x", 1: "y"}
            link_names = {-1: "planar_base", 0: PLANAR_LINKS[0], 1: PLANAR_LINKS[1]}
        else:
            if spec.model == "panda":
                path = str(Path(pybullet_data.getDataPath()) / PANDA_URDF)
                joints, tool = PANDA_JOINTS, PANDA_TOOL
            else:
                path, joints, tool = spec.urdf, spec.joints, spec.tool_link
            uid = self._load_urdf(path, base[:3, 3], transforms.matrix_to_quat(base[:3, :3]),
                                  1.0, lambda message: entry_error(self.scene, message,
                                                                   "robot", 0, "urdf"))
            pb_joint_names = {j: pb.getJointInfo(uid, j, physicsClientId=c)[1].decode()
                              for j in range(pb.getNumJoints(uid, physicsClientId=c))}
        self.robot_id = uid
        by_name = {name: j for j, name in pb_joint_names.items()}
        missing = [j for j in joints if j not in by_name]
        if missing:
            raise entry_error(self.scene, f"the robot has no joint named {', '.join(missing)}; "
                              f"it has {', '.join(by_name)}", "robot", 0, "joints")
        self.joint_names: tuple[str, ...] = tuple(joints)
        self._pb_joints = tuple(by_name[j] for j in joints)
        fixed_values = {}
        if spec.model == "panda":
            self.finger_joints = tuple(by_name[f] for f in PANDA_FINGERS)
            fixed_values = {j: PANDA_FINGER_OPEN for j in self.finger_joints}
            for j in self.finger_joints:
                pb.resetJointState(uid, j, PANDA_FINGER_OPEN, physicsClientId=c)
        self.chain: Chain = measure_chain(pb, c, uid, _pb_names_to_q(pb, c, uid, self._pb_joints),
                                          fixed_values, link_names)
        self.link_names: tuple[str, ...] = self.chain.names
        if tool not in self.chain.index:
            raise entry_error(self.scene, f"the robot has no link named {tool!r}", "robot", 0,
                              "tool_link")
        self.tool_link = tool
        self._tool_index = self.chain.index[tool]
        lower, upper = [], []
        for j in self._pb_joints:
            info = pb.getJointInfo(uid, j, physicsClientId=c)
            lo, hi = info[8], info[9]
            if info[2] == REVOLUTE and hi < lo:  # continuous joint
                lo, hi = -math.pi, math.pi
            lower.append(lo)
            upper.append(hi)
        if spec.model == "planar":
            lo, hi = self._scene_extent()
            lower, upper = list(lo[:2]), list(hi[:2])
        self.lower = np.array(lower, dtype=float)
        self.upper = np.array(upper, dtype=float)
        if spec.start is not None:
            start = np.array(spec.start, dtype=float)
        elif spec.model == "panda":
            start = np.array(PANDA_READY)
        elif spec.model == "planar":
            start = base[:2, 3].copy()
        else:
            start = np.clip(np.zeros(len(joints)), self.lower, self.upper)
        self.start = start
        for v in (self.lower, self.upper, self.start):
            v.flags.writeable = False
        self._set_joints(self.start)

    def _make_planar(self, radius: float, height: float, z: float) -> int:
        pb, c = self.pb, self.client
        col = pb.createCollisionShape(pb.GEOM_CYLINDER, radius=radius, height=height,
                                      physicsClientId=c)
        vis = pb.createVisualShape(pb.GEOM_CYLINDER, radius=radius, length=height,
                                   rgbaColor=(0.9, 0.5, 0.1, 1.0), physicsClientId=c)
        return pb.createMultiBody(
            0.0, -1, -1, [0.0, 0.0, z], linkMasses=[0.1, 0.1],
            linkCollisionShapeIndices=[-1, col], linkVisualShapeIndices=[-1, vis],
            linkPositions=[[0, 0, 0]] * 2, linkOrientations=[[0, 0, 0, 1]] * 2,
            linkInertialFramePositions=[[0, 0, 0]] * 2,
            linkInertialFrameOrientations=[[0, 0, 0, 1]] * 2, linkParentIndices=[0, 1],
            linkJointTypes=[pb.JOINT_PRISMATIC] * 2, linkJointAxis=[[1, 0, 0], [0, 1, 0]],
            physicsClientId=c)

    def _scene_extent(self) -> tuple[np.ndarray, np.ndarray]:
        """Box around all bodies (x, y, z); a unit box about the base when the scene is empty."""
        los, his = [], []
        for uid in self._bodies.values():
            lo, hi = self._aabb(uid)
            los.append(lo)
            his.append(hi)
        if not los:
            base = self.scene.robot.base_pose[:3, 3]
            return base - 1.0, base + 1.0
        return np.min(los, axis=0), np.max(his, axis=0)

    def aabb(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """Axis-aligned box (lo, hi) of a scene body at its start pose."""
        return self._aabb(self._bodies[name])

    def _aabb(self, uid: int) -> tuple[np.ndarray, np.ndarray]:
        pb, c = self.pb, self.client
        los, his = [], []
        for link in range(-1, pb.getNumJoints(uid, physicsClientId=c)):
            lo, hi = pb.getAABB(uid, link, physicsClientId=c)
            los.append(lo)
            his.append(hi)
        return np.min(los, axis=0), np.max(his, axis=0)

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

        Damped least squares from `seed`, the start configuration, then
        random seeds, within the joint limits. `residual` is the norm of
        [position error (m), orientation error (rad)] (position only when
        `position_only`); the caller decides whether it is small enough.
        """
        return solve_ik(self, np.asarray(target, dtype=float), seed, position_only, iterations,
                        restarts, tolerance, rng_seed)

    def body_pose(self, name: str) -> np.ndarray:
        """Start pose (4x4) of a scene body."""
        return self.scene.body(name).matrix

    def base_link(self) -> str:
        return self.link_names[0]

    # ------------------------------------------------------------ replay

    def _set_joints(self, q) -> None:
        for j, v in zip(self._pb_joints, q, strict=True):
            self.pb.resetJointState(self.robot_id, j, float(v), physicsClientId=self.client)

    def set_state(self, q, body_poses: dict | None = None, fingers_closed: bool = False,
                  finger_opening: float | None = None) -> None:
        """Move the robot and bodies in the simulator (for replay only).

        Fingers: open, or closed to `finger_opening` per finger (m) when given,
        else fully closed.
        """
        self._set_joints(np.asarray(q, dtype=float))
        if self.finger_joints:
            value = PANDA_FINGER_OPEN
            if fingers_closed:
                value = 0.0 if finger_opening is None else float(finger_opening)
            for j in self.finger_joints:
                self.pb.resetJointState(self.robot_id, j, value, physicsClientId=self.client)
        for name, t in (body_poses or {}).items():
            t = np.asarray(t, dtype=float)
            if t.shape == (7,):
                t = transforms.pose_from_xyzquat(t)
            self.pb.resetBasePositionAndOrientation(
                self._bodies[name], t[:3, 3], transforms.matrix_to_quat(t[:3, :3]),
                physicsClientId=self.client)

    def camera_image(self, width: int, height: int, eye, target, up=(0.0, 0.0, 1.0),
                     fov: float = 50.0) -> np.ndarray:
        """(height, width, 3) uint8 RGB image of the current state (TinyRenderer)."""
        pb = self.pb
        view = pb.computeViewMatrix(list(eye), list(target), list(up), physicsClientId=self.client)
        proj = pb.computeProjectionMatrixFOV(fov, width / height, 0.01, 20.0,
                                             physicsClientId=self.client)
        _, _, rgba, _, _ = pb.getCameraImage(width, height, view, proj,
                                             renderer=pb.ER_TINY_RENDERER,
                                             physicsClientId=self.client)
        image = np.asarray(rgba, dtype=np.uint8).reshape(height, width, 4)
        return np.ascontiguousarray(image[:, :, :3])

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """(lo, hi) corners of a box around the scene and the robot as it stands now."""
        los, his = [], []
        for uid in [*self._bodies.values(), self.robot_id]:
            lo, hi = self._aabb(uid)
            los.append(lo)
            his.append(hi)
        return np.min(los, axis=0), np.max(his, axis=0)

    # ------------------------------------------------------------ for collision.py

    def pb_body(self, name: str) -> int:
        return self._bodies[name]


def _pb_names_to_q(pb, client, uid, pb_joints) -> dict[str, int]:
    names = {}
    for i, j in enumerate(pb_joints):
        names[pb.getJointInfo(uid, j, physicsClientId=client)[1].decode()] = i
    return names

