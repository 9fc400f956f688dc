"""A URDF arm into a PyBullet client: its file read first (joints from the tree,
every name the scene gives checked against it), then loaded; and its fingers."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.arms import Arm
from tampcli.geometry.chain import FIXED, Chain, ChainLink
from tampcli.geometry.scene_check import entry_error
from tampcli.geometry.urdf_file import Urdf, read_urdf
from tampcli.geometry.world._load import load_urdf


@dataclass(frozen=True)
class FingerJoints:
    """The gripper's joints in the simulator: the named ones and those mimicking them."""

    names: tuple[str, ...]  # the scene's finger joints (leaders)
    pb: tuple[int, ...]  # every finger joint, leaders first
    open: tuple[float, ...]  # per joint of `pb`
    closed: tuple[float, ...]
    links: tuple[int, ...]  # links the fingers move
    leaders: tuple[int, ...]  # per joint of `pb`, the index in `names` of its leader

    def at(self, t: float) -> tuple[float, ...]:
        """Joint values a fraction t of the way from open (0) to closed (1)."""
        return tuple(o + t * (c - o) for o, c in zip(self.open, self.closed, strict=True))

    def expand(self, named) -> tuple[float, ...]:
        """Every joint's value (`pb`'s order) from the named joints' values: a joint
        that mimics one goes the same fraction of its travel."""
        named = [float(v) for v in named]
        if len(named) != len(self.names):
            raise ValueError(f"{len(named)} finger values for the joints {self.names}")
        t = [(v - self.open[i]) / (self.closed[i] - self.open[i]) for i, v in enumerate(named)]
        return tuple(named[i] if j == i else o + t[i] * (c - o)
                     for j, (o, c, i) in enumerate(zip(self.open, self.closed, self.leaders,
                                                       strict=True)))


@dataclass(frozen=True)
class LoadedArm:
    uid: int
    joints: tuple[str, ...]
    fingers: FingerJoints | None


def load_arm(pb, client: int, scene, arm: Arm, visuals: bool = True) -> LoadedArm:
    """Load `arm` at the scene's robot base (`visuals`: load_urdf's); a located SceneError
    for what does not fit."""
    spec = scene.robot
    file_key = "urdf" if spec.model == "urdf" else "model"

    def error(message: str, key: str):
        return entry_error(scene, message, "robot", 0, key)

    path = arm.path()
    try:
        urdf = read_urdf(path)
    except ValueError as e:
        raise error(str(e), file_key) from None
    base = spec.base_pose
    uid = load_urdf(pb, client, path, base[:3, 3], transforms.matrix_to_quat(base[:3, :3]), 1.0,
                    lambda message: error(message, file_key), arm.package_paths,
                    "; name more folders in `package_paths`"
                    if spec.model == "urdf" and not arm.package_paths else "", visuals)
    _check_names(urdf, arm, error)
    finger_names = arm.fingers.joints if arm.fingers else ()
    followers = urdf.followers(finger_names)
    joints = arm.joints or urdf.arm_joints(arm.tool_link, (*finger_names, *followers))
    if not joints:
        raise error(f"no movable joint between the base and {arm.tool_link!r}; name the arm's "
                    "joints in `joints`", "tool_link")
    by_name = {pb.getJointInfo(uid, j, physicsClientId=client)[1].decode(): j
               for j in range(pb.getNumJoints(uid, physicsClientId=client))}
    missing = [j for j in joints if j not in by_name]
    if missing:
        raise error(f"the robot has no joint named {', '.join(missing)}; it has "
                    f"{', '.join(by_name)}", "joints")
    fingers = None
    if arm.fingers is not None:
        fingers = _finger_joints(pb, client, uid, arm, followers, by_name)
    return LoadedArm(uid, tuple(joints), fingers)


def _check_names(urdf: Urdf, arm: Arm, error) -> None:
    links = set(urdf.links)
    if arm.tool_link not in links:
        raise error(f"{urdf.path} has no link {arm.tool_link!r}; its links: "
                    f"{', '.join(urdf.links)}", "tool_link")
    if arm.tool_frame is not None and arm.tool_frame not in links:
        raise error(f"{urdf.path} has no link {arm.tool_frame!r}; its links: "
                    f"{', '.join(urdf.links)}", "tool_offset")
    movable = [j.name for j in urdf.joints if j.movable]
    for name in arm.joints or ():
        if name not in movable:
            raise error(f"{name!r} is no movable joint of {urdf.path}; its movable joints: "
                        f"{', '.join(movable)}", "joints")
    if arm.fingers is None:
        return
    for name in arm.fingers.joints:
        if name not in movable:
            raise error(f"fingers: {name!r} is no movable joint of {urdf.path}; its movable "
                        f"joints: {', '.join(movable)}", "fingers")
        if name in (arm.joints or ()):
            raise error(f"fingers: {name!r} is also in `joints`: a finger opens and closes, "
                        "the planner does not move it", "fingers")
        if name in {j.name for j in urdf.path_to(arm.tool_link)}:
            raise error(f"fingers: {name!r} moves the tool link {arm.tool_link!r}; fix the "
                        "tool to the hand, not to a finger", "fingers")


def _finger_joints(pb, client, uid, arm: Arm, followers, by_name) -> FingerJoints:
    spec = arm.fingers
    pb_joints = [by_name[n] for n in spec.joints]
    open_, closed = list(spec.open), list(spec.closed)
    leaders = list(range(len(spec.joints)))
    for name, (leader, mult, off) in followers.items():
        i = spec.joints.index(leader)
        leaders.append(i)
        pb_joints.append(by_name[name])
        open_.append(mult * spec.open[i] + off)
        closed.append(mult * spec.closed[i] + off)
    parents = {j: pb.getJointInfo(uid, j, physicsClientId=client)[16]
               for j in range(pb.getNumJoints(uid, physicsClientId=client))}
    moved = set(pb_joints)
    changed = True
    while changed:
        changed = False
        for j, parent in parents.items():
            if j not in moved and parent in moved:
                moved.add(j)
                changed = True
    return FingerJoints(spec.joints, tuple(pb_joints), tuple(open_), tuple(closed),
                        tuple(sorted(moved)), tuple(leaders))


def closing_fraction(pb, client: int, robot: int, fingers: FingerJoints, bodies,
                     steps: int = 8) -> float:
    """How far (0 open .. 1 closed) the fingers close before they touch one of `bodies`
    (unique ids), by bisection; the joints are left at the result."""

    def put(t: float) -> None:
        for j, v in zip(fingers.pb, fingers.at(t), strict=True):
            pb.resetJointState(robot, j, v, physicsClientId=client)

    def touches(t: float) -> bool:
        put(t)
        links = set(fingers.links)
        return any(point[3] in links
                   for body in bodies
                   for point in pb.getClosestPoints(robot, body, 0.0, physicsClientId=client))

    if not bodies or not touches(1.0):
        put(1.0)
        return 1.0
    if touches(0.0):
        return 0.0
    lo, hi = 0.0, 1.0
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        if touches(mid):
            hi = mid
        else:
            lo = mid
    put(lo)
    return lo


TOOL_FRAME = "tool_frame"


def tool_frame(scene, chain: Chain, arm: Arm | None, planar_tool: str) -> tuple[Chain, str]:
    """(the chain, with a link for the tool frame when it is an offset; the tool frame's
    link name)."""
    if arm is None:
        return chain, planar_tool
    flange = chain.index[arm.tool_link]
    if arm.tool_frame is not None:
        i = chain.index[arm.tool_frame]
        while i != flange:
            link = chain.links[i]
            if link.parent < 0 or link.joint_type != FIXED:
                raise entry_error(scene, f"the link {arm.tool_frame!r} is not fixed to the tool "
                                  f"link {arm.tool_link!r}: a joint moves it relative to it",
                                  "robot", 0, "tool_offset")
            i = link.parent
        return chain, arm.tool_frame
    if arm.tool_offset is None:
        return chain, arm.tool_link
    name = TOOL_FRAME
    while name in chain.index:
        name += "_"
    origin = transforms.pose_from_xyzquat(arm.tool_offset)
    tcp = ChainLink(name, flange, origin, FIXED, np.zeros(3), -1, 0.0,
                    chain.links[flange].pb_index)
    return Chain([*chain.links, tcp], chain.base_pose, chain.n), name
