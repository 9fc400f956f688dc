"""The checker's own PyBullet scene, built from scene.toml (see checker.py).

Shares no code with tampcli: poses, shapes and the arms are read and built
here, from the file format's meanings (docs/robots.md: which URDF each model is,
its finger joints and their open values).
"""
from __future__ import annotations

import math
import os
import re
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pybullet as pb
import pybullet_data
import tomllib

TOL_PEN, TOL_REST = 1e-3, 5e-3
MESH_MARGIN = 1e-3  # m: PyBullet's collision margin on a mesh's hull
ROOT = Path(__file__).resolve().parents[2]


@dataclass(frozen=True)
class Arm:
    """A built-in arm model as docs/robots.md describes it."""

    urdf: str
    hand: str  # a link rigidly on the tool
    grip_links: tuple[str, ...]  # may touch what the hand holds
    fingers: dict  # finger joint -> its value when open
    closes: bool  # prismatic fingers this checker closes on a held object


def _found(name: str, folder: Path) -> str:
    """A scene's mesh or URDF file: beside the scene, else in pybullet_data (as
    docs/scene.md says files are looked for)."""
    here = folder / name
    return str(here) if here.exists() else _data(name)


def _data(path: str) -> str:
    return os.path.join(pybullet_data.getDataPath(), path)


_XARM_GRIPPER = ("xarm_gripper_base_link", "left_outer_knuckle", "left_finger",
                 "left_inner_knuckle", "right_outer_knuckle", "right_finger",
                 "right_inner_knuckle")
ARMS = {
    "panda": Arm(_data("franka_panda/panda.urdf"), "panda_hand",
                 ("panda_hand", "panda_leftfinger", "panda_rightfinger"),
                 {"panda_finger_joint1": 0.04, "panda_finger_joint2": 0.04}, True),
    # The URDF file tampcli ships for this model (data, not code).
    "kuka_iiwa": Arm(str(ROOT / "tampcli" / "geometry" / "robots" / "kuka_iiwa_gripper.urdf"),
                     "gripper_palm",
                     ("gripper_palm", "gripper_left_finger", "gripper_right_finger"),
                     {"gripper_left_joint": 0.04, "gripper_right_joint": 0.04}, True),
    "xarm6": Arm(_data("xarm/xarm6_with_gripper.urdf"), "xarm_gripper_base_link",
                 _XARM_GRIPPER,
                 dict.fromkeys(("drive_joint", "left_finger_joint", "left_inner_knuckle_joint",
                                "right_outer_knuckle_joint", "right_finger_joint",
                                "right_inner_knuckle_joint"), 0.0), False),
}
# Every finger joint of every arm: a solution that has one among its joints moves them.
FINGERS = tuple(j for arm in ARMS.values() for j in arm.fingers)


def _mimics(urdf: str) -> dict[str, tuple[str, float, float]]:
    """joint -> (the joint it mimics, multiplier, offset), read from the URDF's XML."""
    import xml.etree.ElementTree as ET

    try:
        root = ET.parse(urdf).getroot()
    except (OSError, ET.ParseError):
        return {}
    out = {}
    for joint in root.iter("joint"):
        m = joint.find("mimic")
        if m is not None and m.get("joint"):
            out[joint.get("name")] = (m.get("joint"), float(m.get("multiplier", 1.0)),
                                      float(m.get("offset", 0.0)))
    return out


def pose_of(v) -> tuple[list[float], list[float]]:
    v = [float(x) for x in v]
    if len(v) == 3:
        return v, [0.0, 0.0, 0.0, 1.0]
    if len(v) == 4:
        return v[:3], list(pb.getQuaternionFromEuler([0.0, 0.0, v[3]]))
    return v[:3], list(pb.getQuaternionFromEuler(v[3:6]))


def matrix(pos, quat) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3] = np.array(pb.getMatrixFromQuaternion(quat)).reshape(3, 3)
    m[:3, 3] = pos
    return m


def pose_error(a: np.ndarray, b: np.ndarray) -> tuple[float, float]:
    d = float(np.linalg.norm(a[:3, 3] - b[:3, 3]))
    c = (np.trace(a[:3, :3].T @ b[:3, :3]) - 1.0) / 2.0
    return d, math.acos(max(-1.0, min(1.0, c)))


def _load_urdf(urdf: str, pos, quat, client: int) -> int:
    """loadURDF; a `package://` mesh path not beside the file (where PyBullet looks for
    it) taken from pybullet_data in a copy (the KUKA's meshes)."""
    here = Path(urdf).parent
    text = Path(urdf).read_text()

    def absolute(match: re.Match) -> str:
        rest = match.group(1)
        beside = here / rest
        return str(beside if beside.is_file() else Path(pybullet_data.getDataPath()) / rest)

    fixed = re.sub(r"package://([^\"']+)", absolute, text)
    if fixed == text:
        return pb.loadURDF(urdf, pos, quat, useFixedBase=True, physicsClientId=client)
    with tempfile.TemporaryDirectory() as folder:
        copy = Path(folder) / Path(urdf).name
        copy.write_text(fixed)
        return pb.loadURDF(str(copy), pos, quat, useFixedBase=True, physicsClientId=client)


class Replay:
    """One PyBullet scene built from scene.toml; owns its client."""

    def __init__(self, scene_path: Path):
        self.scene = tomllib.loads(scene_path.read_text())
        self.c = pb.connect(pb.DIRECT)
        self.bodies: dict[str, int] = {}
        self.info: dict[str, dict] = {}
        self._own_boxes: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        for obj in self.scene.get("objects", []):
            self.bodies[obj["name"]] = self._body(obj, scene_path.parent)
            self.info[obj["name"]] = obj
        self.regions = {r["name"]: r for r in self.scene.get("regions", [])}
        self._robot(self.scene["robot"], scene_path.parent)

    def close(self) -> None:
        pb.disconnect(self.c)

    def _body(self, obj: dict, folder: Path) -> int:
        pos, quat = pose_of(obj["pose"])
        shape, size = obj["shape"], obj.get("size", [])
        scale = obj.get("scale", 1.0)  # one number, or one per axis (a mesh's)
        scale = [float(scale)] * 3 if isinstance(scale, (int, float)) else list(scale)
        if shape == "urdf":
            return pb.loadURDF(_found(obj["urdf"], folder), pos, quat, useFixedBase=True,
                               globalScaling=scale[0], physicsClientId=self.c)
        # Built for the shape at hand only: a sphere's size has one number.
        kw = {"box": lambda: dict(shapeType=pb.GEOM_BOX, halfExtents=[s / 2 for s in size]),
              "cylinder": lambda: dict(shapeType=pb.GEOM_CYLINDER, radius=size[0],
                                       height=size[1]),
              "sphere": lambda: dict(shapeType=pb.GEOM_SPHERE, radius=size[0]),
              "mesh": lambda: dict(shapeType=pb.GEOM_MESH,
                                   fileName=_found(obj.get("mesh", ""), folder),
                                   meshScale=scale)}[shape]()
        col = pb.createCollisionShape(physicsClientId=self.c, **kw)
        return pb.createMultiBody(0.0, col, -1, pos, quat, physicsClientId=self.c)

    def _robot(self, robot: dict, folder: Path) -> None:
        pos, quat = pose_of(robot.get("base", [0.0, 0.0, 0.0]))
        self.model = robot.get("model", "panda")
        self.base_z = pos[2]
        if self.model == "planar":
            r, h = robot.get("radius", 0.05), robot.get("height", 0.05)
            col = pb.createCollisionShape(pb.GEOM_CYLINDER, radius=r, height=h,
                                          physicsClientId=self.c)
            self.robot = pb.createMultiBody(0.0, col, -1, pos, physicsClientId=self.c)
            self.links, self.joint_index, self.limits = {-1: "planar"}, {}, {}
            self.base_links = {-1}
            return
        self.arm = ARMS.get(self.model, ARMS["panda"])
        urdf = str(folder / robot["urdf"]) if "urdf" in robot else self.arm.urdf
        self.robot = _load_urdf(urdf, pos, quat, self.c)
        self.mimics = _mimics(urdf)
        self.links = {-1: "base"}
        self.base_links = {-1}
        self.joint_index, self.limits, parent = {}, {}, {}
        for j in range(pb.getNumJoints(self.robot, physicsClientId=self.c)):
            info = pb.getJointInfo(self.robot, j, physicsClientId=self.c)
            self.links[j] = info[12].decode()
            parent[j] = info[16]
            if info[2] != pb.JOINT_FIXED:
                self.joint_index[info[1].decode()] = j
                self.limits[info[1].decode()] = (info[8], info[9])
            elif info[16] in self.base_links:  # fixed to the base: stands where it does
                self.base_links.add(j)
        if "urdf" in robot:
            self.arm = self._own_arm(robot, urdf, parent)
        self._self_pairs(parent)

    def _own_arm(self, robot: dict, urdf: str, parent: dict[int, int]) -> Arm:
        """A scene's own URDF arm (docs/robots.md, "Any URDF arm"): its tool link and
        every link below it may touch what it holds; its fingers stay open (their
        columns are not in a solution file), as the docs say the planner keeps them."""
        tool = robot["tool_link"]
        below = {j for j, n in self.links.items() if n == tool}
        grew = True
        while grew:
            grew = False
            for j, up in parent.items():
                if up in below and j not in below:
                    below.add(j)
                    grew = True
        spec = robot.get("fingers") or {}
        joints = list(spec.get("joints", []))
        opened = spec.get("open", 0.0)
        values = opened if isinstance(opened, list) else [opened] * len(joints)
        return Arm(urdf, tool, tuple(self.links[j] for j in sorted(below)),
                   dict(zip(joints, (float(v) for v in values), strict=True)), False)

    def _self_pairs(self, parent: dict[int, int]) -> None:
        geo = [k for k in self.links if pb.getCollisionShapeData(self.robot, k,
                                                                 physicsClientId=self.c)]

        def up(k: int) -> int:  # nearest ancestor with geometry
            k = parent.get(k, -1)
            while k not in geo and k != -1:
                k = parent.get(k, -1)
            return k

        fingers = {self.joint_index.get(f) for f in self.arm.fingers}
        gripper = {j for j, n in self.links.items() if n in self.arm.grip_links}
        # The gripper's own linkage (the xArm's knuckles) is not a self-collision.
        self.self_pairs = [(a, b) for i, a in enumerate(geo) for b in geo[i + 1:]
                           if up(a) != b and up(b) != a and {a, b} != fingers
                           and not {a, b} <= gripper]

    # -- state --------------------------------------------------------------
    def set_q(self, names: list[str], q, open_fingers: bool) -> None:
        """The arm at q (joints `names`); `open_fingers`: the fingers open too."""
        if self.model == "planar":
            pb.resetBasePositionAndOrientation(self.robot, [q[0], q[1], self.base_z],
                                               [0, 0, 0, 1], physicsClientId=self.c)
            return
        for n, v in zip(names, q, strict=True):
            pb.resetJointState(self.robot, self.joint_index[n], v, physicsClientId=self.c)
        # A joint the URDF makes mimic a given one follows it (the KUKA's right finger
        # mimics its left: a solution gives the left one's column only).
        given = dict(zip(names, q, strict=True))
        for joint, (leader, multiplier, offset) in self.mimics.items():
            if leader in given and joint not in given and joint in self.joint_index:
                pb.resetJointState(self.robot, self.joint_index[joint],
                                   multiplier * float(given[leader]) + offset,
                                   physicsClientId=self.c)
        if open_fingers:
            for f, value in self.arm.fingers.items():
                if f in self.joint_index:
                    pb.resetJointState(self.robot, self.joint_index[f], value,
                                       physicsClientId=self.c)
            # and the joints that mimic them (a URDF arm's right finger)
            for joint, (leader, multiplier, offset) in self.mimics.items():
                if leader in self.arm.fingers and joint not in self.arm.fingers \
                        and joint in self.joint_index:
                    pb.resetJointState(self.robot, self.joint_index[joint],
                                       multiplier * self.arm.fingers[leader] + offset,
                                       physicsClientId=self.c)

    def hand(self) -> np.ndarray:
        if self.model == "planar":
            return matrix(*pb.getBasePositionAndOrientation(self.robot, physicsClientId=self.c))
        k = next((j for j, n in self.links.items() if n == self.arm.hand), max(self.links))
        s = pb.getLinkState(self.robot, k, computeForwardKinematics=True, physicsClientId=self.c)
        return matrix(s[4], s[5])

    def place(self, name: str, m: np.ndarray) -> None:
        q = quaternion(m[:3, :3])
        pb.resetBasePositionAndOrientation(self.bodies[name], m[:3, 3].tolist(), q,
                                           physicsClientId=self.c)

    def close_fingers(self, held: str) -> None:
        """Close both (prismatic) fingers until they touch `held` (PyBullet distances);
        an arm whose fingers this checker does not close keeps them open."""
        if not self.arm.closes:
            return
        d = 0.04
        for _ in range(3):
            self.set_fingers(d)
            gaps = [self._dist(self.robot, self.bodies[held], self.joint_index[f], 0.05)
                    for f in self.arm.fingers]
            d = max(0.0, min(0.04, d - max(0.0, min(gaps))))
        self.set_fingers(d)

    def closing_sweep(self, held: str, start: float = 0.04) -> list[tuple[str, str, float]]:
        """(finger link, body, depth) where the prismatic fingers, closing from `start`
        to where they touch `held` (2 mm steps), pass more than the tolerance into
        anything but `held`: a grip with something between a finger and the object."""
        if not self.arm.closes:
            return []
        self.close_fingers(held)
        touch = pb.getJointState(self.robot, self.joint_index[next(iter(self.arm.fingers))],
                                 physicsClientId=self.c)[0]
        out = {}
        fingers = {self.joint_index[f] for f in self.arm.fingers}
        for d in np.linspace(start, touch, max(2, int(abs(start - touch) / 0.002) + 1)):
            self.set_fingers(float(d))
            for name, body in self.bodies.items():
                if name == held:
                    continue
                for p in pb.getClosestPoints(self.robot, body, 0.0, physicsClientId=self.c):
                    if p[3] in fingers and p[8] < -TOL_PEN:
                        key = (self.links[p[3]], name)
                        out[key] = min(out.get(key, 0.0), p[8])
        self.set_fingers(float(touch))
        return [(a, b, d) for (a, b), d in out.items()]

    def set_fingers(self, d: float) -> None:
        for f in self.arm.fingers:
            pb.resetJointState(self.robot, self.joint_index[f], d, physicsClientId=self.c)

    def _dist(self, a: int, b: int, link: int, reach: float) -> float:
        pts = pb.getClosestPoints(a, b, reach, linkIndexA=link, physicsClientId=self.c)
        return min((p[8] for p in pts), default=reach)

    # -- queries ------------------------------------------------------------
    def penetrations(self, held: str | None, grasped: bool, movable: list[str],
                     everything: bool):
        """(name A, name B, depth) for each pair deeper than the tolerance; `grasped`:
        the fingers hold `held`, so they and the hand may touch it."""
        out = []
        stand = self.stands_on()
        for name, body in self.bodies.items():
            for p in pb.getClosestPoints(self.robot, body, 0.0, physicsClientId=self.c):
                link = self.links.get(p[3], "?")
                if p[8] >= -TOL_PEN or (grasped and name == held and link in self.arm.grip_links):
                    continue
                if p[3] in self.base_links and name == stand:
                    continue
                out.append((link, name, p[8]))
        names = list(self.bodies)
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                if not (everything and (a in movable or b in movable)) and held not in (a, b):
                    continue
                # PyBullet grows a mesh's convex hull by its 1 mm collision margin: a
                # mesh resting on its support measures 1 mm deep (docs/scene.md).
                tol = TOL_PEN + MESH_MARGIN * sum(
                    self.info.get(n, {}).get("shape") == "mesh" for n in (a, b))
                for p in pb.getClosestPoints(self.bodies[a], self.bodies[b], 0.0,
                                             physicsClientId=self.c):
                    if p[8] < -tol:
                        out.append((a, b, p[8]))
        if self.model != "planar":
            for a, b in self.self_pairs:
                for p in pb.getClosestPoints(self.robot, self.robot, 0.0, a, b,
                                             physicsClientId=self.c):
                    if p[8] < -TOL_PEN:
                        out.append((self.links[a], self.links[b], p[8]))
        return out

    def stands_on(self) -> str | None:
        base = pb.getBasePositionAndOrientation(self.robot, physicsClientId=self.c)[0]
        for name, body in self.bodies.items():
            lo, hi = pb.getAABB(body, physicsClientId=self.c)
            if (lo[0] <= base[0] <= hi[0] and lo[1] <= base[1] <= hi[1]
                    and abs(hi[2] - self.base_z) <= TOL_REST):
                return name
        return None

    def corners(self, name: str) -> np.ndarray:
        """World points whose convex hull is the body (boxes exactly, round bodies to
        72 points a ring, other shapes their bounding box)."""
        obj, body = self.info[name], self.bodies[name]
        m = matrix(*pb.getBasePositionAndOrientation(body, physicsClientId=self.c))
        size = obj.get("size", [])
        if obj["shape"] == "box":
            pts = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1)
                            for z in (-1, 1)]) * np.array(size) / 2
        elif obj["shape"] in ("cylinder", "sphere"):
            r, h = size[0], (size[1] if obj["shape"] == "cylinder" else 2 * size[0])
            t = np.linspace(0, 2 * np.pi, 72, endpoint=False)
            ring = np.stack([r * np.cos(t), r * np.sin(t)], 1)
            pts = np.concatenate([np.c_[ring, np.full(72, z)] for z in (-h / 2, h / 2)])
        else:
            # A mesh's or URDF's box in its own frame (the docs' footprint of a mesh),
            # turned with it: the world AABB of a turned mesh is wider than the mesh,
            # and read in a turned support's frame its corners stuck out (blind34 p04:
            # an octagonal nut 2 deg off its plate, "sticks out by 22.5 mm").
            lo, hi = self._own_box(name)
            pts = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                            for z in (lo[2], hi[2])])
        return pts @ m[:3, :3].T + m[:3, 3]

    def _own_box(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """PyBullet's AABB of the body's base at the origin, unturned (cached)."""
        if name not in self._own_boxes:
            body = self.bodies[name]
            pos, orn = pb.getBasePositionAndOrientation(body, physicsClientId=self.c)
            pb.resetBasePositionAndOrientation(body, (0, 0, 0), (0, 0, 0, 1),
                                               physicsClientId=self.c)
            lo, hi = pb.getAABB(body, physicsClientId=self.c)
            pb.resetBasePositionAndOrientation(body, pos, orn, physicsClientId=self.c)
            self._own_boxes[name] = (np.array(lo), np.array(hi))
        return self._own_boxes[name]

    def footprint(self, name: str) -> tuple[np.ndarray, float]:
        """xy points whose hull is the body's projection, and its bottom z."""
        pts = self.corners(name)
        return pts[:, :2], float(pts[:, 2].min())

    def top_face(self, name: str) -> tuple[np.ndarray, np.ndarray, float]:
        """Frame (4x4, xy used) and half extents of a body's top face, and its height."""
        obj, pts = self.info[name], self.corners(name)
        m = matrix(*pb.getBasePositionAndOrientation(self.bodies[name], physicsClientId=self.c))
        if obj["shape"] == "box":
            return m, np.array(obj["size"][:2]) / 2, float(pts[:, 2].max())
        if obj["shape"] == "cylinder":  # its inscribed square: conservative
            return m, np.full(2, obj["size"][0] / math.sqrt(2)), float(pts[:, 2].max())
        lo, hi = pts.min(0), pts.max(0)
        centre = np.eye(4)
        centre[:2, 3] = (lo[:2] + hi[:2]) / 2
        return centre, (hi[:2] - lo[:2]) / 2, float(hi[2])

    def rests(self, name: str) -> bool:
        """The body's bottom lies on the top face of a body under its centre."""
        pts, bottom = self.footprint(name)
        cx, cy = pts.mean(0)
        for other in self.bodies:
            if other == name:
                continue
            frame, half, top = self.top_face(other)
            local = (np.array([cx, cy]) - frame[:2, 3]) @ frame[:2, :2]
            if np.all(np.abs(local) <= half + 1e-6) and abs(top - bottom) <= TOL_REST:
                return True
        return False


def quaternion(r: np.ndarray) -> list[float]:
    w = math.sqrt(max(0.0, 1.0 + r[0, 0] + r[1, 1] + r[2, 2])) / 2
    x = math.copysign(math.sqrt(max(0.0, 1 + r[0, 0] - r[1, 1] - r[2, 2])) / 2, r[2, 1] - r[1, 2])
    y = math.copysign(math.sqrt(max(0.0, 1 - r[0, 0] + r[1, 1] - r[2, 2])) / 2, r[0, 2] - r[2, 0])
    z = math.copysign(math.sqrt(max(0.0, 1 - r[0, 0] - r[1, 1] + r[2, 2])) / 2, r[1, 0] - r[0, 1])
    return [x, y, z, w]
