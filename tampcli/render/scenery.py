"""Things only a video needs: goal regions drawn as thin plates, and the points
automatic framing must keep in view.

Added as the World's visual boxes, which have no collision shapes, so they
can never change a collision query.
"""

from __future__ import annotations

import numpy as np

from tampcli.render.camera import box_corners

PLATE_THICKNESS = 0.002  # m: thick enough not to z-fight with the support's top face


def add_regions(world) -> int:
    """Draw every region of the scene on its support; returns how many were drawn."""
    drawn = 0
    names = set(world.body_names)
    for region in world.scene.regions:
        if region.on not in names:
            continue
        top = world.aabb(region.on, base_only=True)[1][2]
        half = [region.size[0] / 2, region.size[1] / 2, PLATE_THICKNESS / 2]
        world.add_visual_box([region.center[0], region.center[1], top + PLATE_THICKNESS / 2],
                             half, region.color)
        drawn += 1
    return drawn


def visible_points(world, states, samples: int = 12) -> np.ndarray:
    """Corners of every body's and robot link's box, at `samples` states spread
    over the replay: what the camera must keep in the frame.

    Boxes per part, not one box around all, so empty space above a table does
    not push the camera back. Poses the world (it is the planning world).
    """
    picks = np.unique(np.linspace(0, len(states) - 1, min(samples, len(states))).astype(int))
    points = []
    for i in picks:
        state = states[i]
        world.set_state(np.asarray(state.q), state.poses, fingers_closed=state.fingers_closed,
                        fingers=state.fingers)
        for lo, hi in world.part_boxes():
            points.append(box_corners(lo, hi))
    return np.concatenate(points)
