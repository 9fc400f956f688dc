"""The physics replay grasps where the plan grasps: at the pick's configuration, not
part of the way into the carry that follows it, so a carry that sets off sideways
still puts the object down where the plan puts it."""

from __future__ import annotations

import numpy as np
from render_solutions import PANDA, interpolate, top_down_reach

from tampcli.geometry import transforms
from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.render.inputs import load_inputs
from tampcli.render.physics import replay_physics
from tampcli.solution import Phase, Solution


def _sideways_carry(steps: int) -> Solution:
    """Cube a picked and carried 35 cm sideways, 5 mm over the table, then set down
    in the goal region; `steps` segments between corners."""
    scene = load_scene(PANDA / "p01.scene.toml", geometric=False)
    with World(scene) as world:
        reach = top_down_reach(world)
        a_start = world.body_pose("a")

        a_xyz = a_start[:3, 3]
        goal_xyz = np.array([0.45, 0.3, 0.025])
        above_a = reach(a_xyz + [0, 0, 0.15], world.start)
        grasp_a = reach(a_xyz, above_a)
        # off the cube's spot along the table first: the first carry segment is sideways
        aside = reach(a_xyz + [0, 0.35, 0.005], grasp_a)
        above_goal = reach(goal_xyz + [0, 0, 0.15], aside)
        place_goal = reach(goal_xyz, above_goal)
        a_goal = world.tool_pose(place_goal) @ transforms.pose_inverse(
            world.tool_pose(grasp_a)) @ a_start
        b_start = world.body_pose("b")
        joints, tool = list(world.joint_names), world.tool_link
    free1 = interpolate([world.start, above_a, grasp_a], steps)
    carry = interpolate([grasp_a, aside, above_goal, place_goal], steps)
    free2 = interpolate([place_goal, above_goal, world.start], steps)
    trajectory = free1 + carry[1:] + free2[1:]
    i1 = len(free1) - 1
    i2 = i1 + len(carry) - 1
    phases = (Phase(None, 0, i1), Phase("(pick a table)", i1, i1, "a"),
              Phase(None, i1, i2, "a"), Phase("(place a goal)", i2, i2, None),
              Phase(None, i2, len(trajectory) - 1))
    pose = transforms.xyzquat_from_pose
    return Solution(
        domain=str(PANDA / "domain.pddl"), problem=str(PANDA / "p01.pddl"),
        scene=str(PANDA / "p01.scene.toml"), status="solved",
        plan=("(pick a table)", "(place a goal)"), symbolic_cost=2.0, cost=1.0,
        lower_bound=1.0, robot={"model": "panda", "joints": joints, "tool_link": tool},
        trajectory=tuple(tuple(float(v) for v in q) for q in trajectory), phases=phases,
        objects={"a": [pose(a_start)] * 3 + [pose(a_goal)] * 3,
                 "b": [pose(b_start)] * 6})


def test_a_sideways_carry_sets_the_object_down_where_planned():
    solution = _sideways_carry(steps=1)
    replay = replay_physics(load_inputs(solution))
    a = next(o for o in replay.objects if o.name == "a")
    # Grasped half a simulation step into the carry, the cube was carried 0.5 mm off
    # its grip and ended 0.45 mm from its planned pose; grasped at the pick, 0.1 mm.
    assert a.distance < 2e-4, a.distance
