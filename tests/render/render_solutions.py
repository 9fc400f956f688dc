"""Hand-made solutions for the render tests: real scenes, real IK, joint-space
interpolation, phases and object poses laid out as docs/formats.md says."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.solution import Phase, Solution

DATA = Path(__file__).resolve().parent / "data"
PANDA = DATA / "panda"
PLANAR = DATA / "planar"


def interpolate(configs, steps: int) -> list[np.ndarray]:
    """`steps` segments between each pair of configs, ends included once."""
    out = [np.asarray(configs[0], dtype=float)]
    for a, b in zip(configs, configs[1:], strict=False):
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        out += [a + (b - a) * k / steps for k in range(1, steps + 1)]
    return out


def top_down_reach(world):
    """reach(xyz, seed) -> the configuration with the tool at xyz, pointing as at start."""
    down = world.tool_pose(world.start)

    def reach(xyz, seed):
        target = down.copy()
        target[:3, 3] = xyz
        q, residual = world.ik(target, seed)
        assert residual < 1e-4, residual
        return q

    return reach


def _pose(t) -> list[float]:
    return transforms.xyzquat_from_pose(t)


def panda_solution(folder: Path = PANDA, scene: str = "p01.scene.toml",
                   problem: str = "p01.pddl", steps: int = 6,
                   with_note: bool = False) -> Solution:
    """Pick cube a from the table and place it in the goal region."""
    sc = load_scene(folder / scene, geometric=False)
    with World(sc) as world:
        reach = top_down_reach(world)
        a_start = world.body_pose("a")
        b_start = world.body_pose("b")

        a_xyz = a_start[:3, 3]
        goal_xyz = np.array([0.45, 0.3, 0.025])
        above_a = reach(a_xyz + [0, 0, 0.15], world.start)
        grasp_a = reach(a_xyz, above_a)
        above_goal = reach(goal_xyz + [0, 0, 0.15], above_a)
        place_goal = reach(goal_xyz, above_goal)
        a_goal = world.tool_pose(place_goal) @ transforms.pose_inverse(
            world.tool_pose(grasp_a)) @ a_start
        joints = list(world.joint_names)
        tool = world.tool_link
    free1 = interpolate([world.start, above_a, grasp_a], steps)
    carry = interpolate([grasp_a, above_a, above_goal, place_goal], steps)
    free2 = interpolate([place_goal, above_goal, world.start], steps)
    trajectory = free1 + carry[1:] + free2[1:]
    i1 = len(free1) - 1
    i2 = i1 + len(carry) - 1
    i3 = len(trajectory) - 1
    phases = [Phase(None, 0, i1), Phase("(pick a table)", i1, i1, "a"),
              Phase(None, i1, i2, "a"), Phase("(place a goal)", i2, i2, None),
              Phase(None, i2, i3)]
    plan = ["(pick a table)", "(place a goal)"]
    a_poses = [a_start] * 3 + [a_goal] * 3
    if with_note:
        phases.append(Phase("(note b)", i3, i3))
        plan.append("(note b)")
        a_poses.append(a_goal)
    objects = {"a": [_pose(t) for t in a_poses], "b": [_pose(b_start)] * len(a_poses)}
    return Solution(
        domain=str(folder / "domain.pddl"), problem=str(folder / problem),
        scene=str(folder / scene), status="solved", plan=tuple(plan),
        symbolic_cost=float(len(plan)), cost=1.0, lower_bound=1.0,
        robot={"model": "panda", "joints": joints, "tool_link": tool},
        trajectory=tuple(tuple(float(v) for v in q) for q in trajectory),
        phases=tuple(phases), objects=objects)


def planar_solution(steps: int = 6) -> Solution:
    """Push the box from the start region into the goal region."""
    box = np.array([0.3, 0.3, 0.025])
    behind = box[:2] - [0.0, 0.03 + 0.05]
    shift = np.array([0.0, 0.4])
    approach = interpolate([[0.0, 0.0], [0.3, 0.0], behind], steps)
    push = interpolate([behind, behind + shift], 2 * steps)
    retreat = interpolate([behind + shift, behind + shift + [0.25, -0.1]], steps)
    trajectory = approach + push[1:] + retreat[1:]
    i1 = len(approach) - 1
    i2 = i1 + len(push) - 1
    phases = [Phase(None, 0, i1), Phase("(push box start goal)", i1, i2, "box"),
              Phase(None, i2, len(trajectory) - 1)]
    start = box.tolist() + [0.0, 0.0, 0.0, 1.0]
    end = (box + [0.0, 0.4, 0.0]).tolist() + [0.0, 0.0, 0.0, 1.0]
    return Solution(
        domain=str(PLANAR / "domain.pddl"), problem=str(PLANAR / "p01.pddl"),
        scene=str(PLANAR / "p01.scene.toml"), status="solved",
        plan=("(push box start goal)",), symbolic_cost=1.0, cost=1.0,
        robot={"model": "planar", "joints": ["x", "y"], "tool_link": "planar_body"},
        trajectory=tuple(tuple(float(v) for v in q) for q in trajectory),
        phases=tuple(phases), objects={"box": [start, start, end, end]})
