"""Things only a video needs: goal regions drawn as thin plates, and the points
automatic framing must keep in view.

Added through the World's public client handle, as visual shapes without
collision shapes, so they can never change a collision query.
"""

from __future__ import annotations

import numpy as np

from tampcli.render.camera import box_corners

PLATE_THICKNESS = 0.002  # m: thick enough not to z-fight with the support's top face


def add_regions(world) -> int:
    """Draw every region of the scene on its support; returns how many were drawn."""
    pb, client = world.pb, world.client
    drawn = 0
    for region in world.scene.regions:
        try:
            support = world.pb_body(region.on)
        except KeyError:
            continue
        top = pb.getAABB(support, -1, physicsClientId=client)[1][2]
        half = [region.size[0] / 2, region.size[1] / 2, PLATE_THICKNESS / 2]
        color = list(region.color)
        visual = pb.createVisualShape(pb.GEOM_BOX, halfExtents=half, rgbaColor=color,
                                      physicsClientId=client)
        pb.createMultiBody(0.0, -1, visual,
                           [region.center[0], region.center[1], top + PLATE_THICKNESS / 2],
                           physicsClientId=client)
        drawn += 1
    return drawn


def visible_points(world, states, samples: int = 12) -> np.ndarray:
    """Corners of every body's and robot link's box, at `samples` states spread
    over the replay: what the camera must keep in the frame.

    Boxes per part, not one box around all, so empty space above a table does
    not push the camera back. Poses the world (it is the planning world).
    """
    pb, client = world.pb, world.client
    picks = np.unique(np.linspace(0, len(states) - 1, min(samples, len(states))).astype(int))
    parts = [(world.pb_body(name), -1) for name in world.body_names]
    robot = world.robot_id
    parts += [(robot, link) for link in range(-1, pb.getNumJoints(robot,
                                                                 physicsClientId=client))]
    points = []
    for i in picks:
        state = states[i]
        world.set_state(np.asarray(state.q), state.poses, fingers_closed=state.fingers_closed)
        for uid, link in parts:
            lo, hi = pb.getAABB(uid, link, physicsClientId=client)
            points.append(box_corners(lo, hi))
    return np.concatenate(points)
