"""A hand-made solution that stacks the test tower (data/tower): real scene, real IK,
the hand pointing down, each cube carried over its target and lowered onto it.
`offsets` shift a cube's target from the centre of the one below: aligned, the
tower stands; overhanging, it must not."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.solution import Phase, Solution

ROOT = Path(__file__).resolve().parents[2]
TOWER = Path(__file__).resolve().parent / "data" / "tower"
DOMAIN = ROOT / "domains" / "arm-pick-place" / "domain.pddl"
MODES = ROOT / "domains" / "arm-pick-place" / "modes.toml"
ORDER = (("c", "d"), ("b", "c"), ("a", "b"))  # (cube, onto), bottom up
STEPS = 5  # joint-space segments between two poses


def _interpolate(configs) -> list[np.ndarray]:
    out = [np.asarray(configs[0], dtype=float)]
    for a, b in zip(configs, configs[1:], strict=False):
        out += [a + (b - a) * k / STEPS for k in range(1, STEPS + 1)]
    return out


def tower_solution(offsets: dict[str, tuple[float, float]] | None = None,
                   lift: bool = True) -> Solution:
    """Stack c on d, b on c, a on b; `offsets[cube]` (x, y in m) off-centre. Without
    `lift` the hand leaves each placed cube sideways, its finger sweeping through it."""
    offsets = offsets or {}
    scene = load_scene(TOWER / "tower4.scene.toml", geometric=False)
    with World(scene) as world:
        down = world.tool_pose(world.start)
        seed = [np.asarray(world.start)]

        def reach(xyz):
            target = down.copy()
            target[:3, 3] = xyz
            q, residual = world.ik(target, seed[0])
            assert residual < 1e-5, residual
            seed[0] = q
            return q

        poses = {b.name: b.matrix for b in scene.bodies if not b.fixed}
        sizes = {b.name: b.size[2] for b in scene.bodies if not b.fixed}
        trajectory = [np.asarray(world.start, dtype=float)]
        phases, plan, boundaries = [], [], [dict(poses)]
        up = lift
        lift: list[np.ndarray] = []  # straight up from the last place first
        for cube, onto in ORDER:
            start = poses[cube][:3, 3]
            below = poses[onto][:3, 3]
            dx, dy = offsets.get(cube, (0.0, 0.0))
            goal = below + [dx, dy, 0.5 * sizes[onto] + 0.5 * sizes[cube]]
            above_start, grasp = reach(start + [0, 0, 0.15]), reach(start)
            above_goal = reach(goal + [0, 0, 0.15])
            near_goal = reach(goal + [0, 0, 0.04])
            place = reach(goal)
            for kind, configs in (("free", [*lift, above_start, grasp]),
                                  ("carry", [above_start, above_goal, near_goal, place])):
                first = len(trajectory) - 1
                trajectory += _interpolate([trajectory[-1], *configs])[1:]
                last = len(trajectory) - 1
                attached = cube if kind == "carry" else None
                phases.append(Phase(None, first, last, attached))
                if kind == "carry":
                    poses[cube] = world.tool_pose(place) @ transforms.pose_inverse(
                        world.tool_pose(grasp)) @ poses[cube]
                boundaries.append(dict(poses))
                action = f"(pick {cube} start)" if kind == "free" else f"(stack {cube} {onto})"
                phases.append(Phase(action, last, last, cube if kind == "free" else None))
                plan.append(action)
                boundaries.append(dict(poses))
            lift = [reach(goal + [0, 0, 0.04]), above_goal] if up else []
        first = len(trajectory) - 1
        trajectory += _interpolate([trajectory[-1], *(lift or [above_goal])])[1:]
        phases.append(Phase(None, first, len(trajectory) - 1))
        boundaries.append(dict(poses))
        joints, tool = list(world.joint_names), world.tool_link
    objects = {name: [transforms.xyzquat_from_pose(b[name]) for b in boundaries]
               for name in boundaries[0]}
    return Solution(
        domain=str(DOMAIN), problem=str(TOWER / "tower4.pddl"),
        scene=str(TOWER / "tower4.scene.toml"), modes=str(MODES), status="solved",
        plan=tuple(plan), symbolic_cost=float(len(plan)), cost=1.0, lower_bound=1.0,
        robot={"model": "panda", "joints": joints, "tool_link": tool},
        trajectory=tuple(tuple(float(v) for v in q) for q in trajectory),
        phases=tuple(phases), objects=objects)
