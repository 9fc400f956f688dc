"""Reshape a solution.json (as a dict) into other shapes the format allows:
motions split at a waypoint, a retreat appended, finger columns removed or added."""

from __future__ import annotations

import copy

import numpy as np

from tampcli.geometry import transforms


def split_motion(data: dict, k: int, at: int, world) -> dict:
    """phases[k] (a motion) as two motions meeting at waypoint `at`; the new
    boundary's poses: the carried object follows the tool, the rest stay."""
    data = copy.deepcopy(data)
    phase = data["phases"][k]
    assert phase["action"] is None and phase["start"] < at < phase["end"], phase
    data["phases"][k:k + 1] = [dict(phase, end=at), dict(phase, start=at)]
    q = np.asarray(data["trajectory"], dtype=float)
    for name, poses in data["objects"].items():
        pose = poses[k]
        if name == phase["attached"]:
            grasp = transforms.pose_inverse(world.tool_pose(q[phase["start"]])) @ \
                transforms.pose_from_xyzquat(pose)
            pose = [float(v) for v in
                    transforms.xyzquat_from_pose(world.tool_pose(q[at]) @ grasp)]
        poses.insert(k + 1, list(pose))
    return data


def arm_only(data: dict) -> dict:
    """The file without finger columns (what `solve` writes where the hand stays
    fully open): the shape the other reshapings start from."""
    data = copy.deepcopy(data)
    joints = data["robot"]["joints"]
    keep = [j for j, name in enumerate(joints) if not name.startswith("panda_finger")]
    data["robot"]["joints"] = [joints[j] for j in keep]
    data["trajectory"] = [[q[j] for j in keep] for q in data["trajectory"]]
    return data


def add_retreat(data: dict, waypoints: list, attached: str | None = None) -> dict:
    """A motion phase after the last one, through `waypoints` (the last waypoint first)."""
    data = copy.deepcopy(data)
    last = len(data["trajectory"]) - 1
    data["trajectory"] += [list(map(float, q)) for q in waypoints]
    data["phases"].append({"action": None, "start": last, "end": len(data["trajectory"]) - 1,
                           "attached": attached})
    for poses in data["objects"].values():
        poses.append(list(poses[-1]))
    return data


def add_fingers(data: dict, opening, order: tuple[str, ...] | None = None) -> dict:
    """Finger columns: `opening(i)` at waypoint i; `order` the joints' new order."""
    data = copy.deepcopy(data)
    joints = data["robot"]["joints"] + ["panda_finger_joint1", "panda_finger_joint2"]
    rows = [list(q) + [opening(i), opening(i)] for i, q in enumerate(data["trajectory"])]
    order = order or tuple(joints)
    columns = [joints.index(name) for name in order]
    data["robot"]["joints"] = list(order)
    data["trajectory"] = [[row[c] for c in columns] for row in rows]
    return data
