"""`--physics`: replay a solution with PyBullet dynamics and measure how far the
objects end up from where the plan put them.

The robot's joints track the replay's timeline under position control; a
carried object hangs from the tool by a fixed constraint (collisions between
it and the robot are off meanwhile, as the planner assumes); pushed objects
are moved by contact alone; gravity acts throughout. A large drift means the
plan relies on something physics does not grant: an unstable placement, a
push that slips, a motion too fast to track.

Works on a World of its own, through the Dynamics it starts: the forces and
masses are this module's, the simulator stays the World's.
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.geometry import transforms
from tampcli.render.replay import Replay

HZ = 240.0  # PyBullet's default step
SETTLE_SECONDS = 1.0  # after the last waypoint, let things come to rest
OBJECT_MASS = 0.1  # kg: light enough for any arm to carry
JOINT_FORCE = {"planar": 50.0}  # N for the planar robot's prismatic joints
JOINT_FORCE_OTHER = 200.0  # N m: stronger than gravity on a Panda's links
FINGER_FORCE = 20.0
FRICTION = 0.6
GRASP_FORCE = 500.0  # N: the most the grasp constraint pulls the held object with


def replay_physics(inputs, mode_kind=None, speed: float | None = None, hz: float = HZ,
                   settle: float = SETTLE_SECONDS) -> dict:
    """Simulate and compare; returns per-object drift and the robot's tracking error.

    The timing is the replay's default (or `speed`), not the video's: planners
    assume quasi-static motion, and a 1-second video of a long push would fling
    the object.
    """
    from tampcli.geometry.world import World

    with World(inputs.scene) as world:
        replay = Replay(inputs.solution, world.tool_pose, mode_kind=mode_kind, speed=speed,
                        pause=0.25)
        force = JOINT_FORCE.get(inputs.solution.robot.get("model"), JOINT_FORCE_OTHER)
        sim = world.start_dynamics(hz)
        first = replay.state_at(0.0)
        world.set_state(np.asarray(first.q), first.poses, fingers_closed=False)
        sim.make_dynamic(first.poses, OBJECT_MASS, FRICTION)
        steps = 0
        tracking = 0.0
        n = int(math.ceil(replay.duration * hz))
        for i in range(n + int(settle * hz)):
            state = replay.state_at(min(i / hz, replay.duration))
            sim.hold(state.held, GRASP_FORCE)
            sim.drive(state.q, force, FINGER_FORCE)
            sim.step()
            steps += 1
            if i % 8 == 0:
                error = np.max(np.abs(sim.joint_positions() - np.asarray(state.q)))
                tracking = max(tracking, float(error))
        final = replay.state_at(replay.duration)
        objects = {}
        for name, planned in final.poses.items():
            simulated = sim.pose_of(name)
            rot = planned[:3, :3].T @ simulated[:3, :3]
            angle = float(np.linalg.norm(transforms.rotation_log(rot)))
            objects[name] = {
                "distance": float(np.linalg.norm(simulated[:3, 3] - planned[:3, 3])),
                "angle_deg": math.degrees(angle),
                "planned": transforms.xyzquat_from_pose(planned),
                "simulated": transforms.xyzquat_from_pose(simulated),
            }
    return {"seconds": steps / hz, "steps": steps, "hz": hz, "objects": objects,
            "max_distance": max((o["distance"] for o in objects.values()), default=0.0),
            "tracking_error": tracking}
