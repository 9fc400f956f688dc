"""Does a checked solution fit the scene it names? The same robot (model, joints,
tool link) and poses for exactly the scene's movable bodies. `render` and
`validate` both refuse a misfit as bad input, before looking at any motion."""

from __future__ import annotations

import numpy as np

from tampcli.errors import SolutionFileError
from tampcli.solution_read import SolutionFile


def check_fits_world(solution: SolutionFile, world, scene_path) -> None:
    """`world`: a geometry.world.World of the solution's scene (its robot and bodies)."""
    sol, path = solution.canonical, solution.path
    model, scene_model = sol.robot.get("model"), world.scene.robot.model
    if model is None:
        raise SolutionFileError(f"missing (the scene's robot is {scene_model!r})", path,
                                key="robot.model")
    if model != scene_model:
        raise SolutionFileError(f"{model!r} but the scene {scene_path} has a {scene_model!r} "
                                "robot", path, key="robot.model")
    scene_joints = tuple(world.joint_names)
    known = scene_joints + world.finger_names
    unknown = [name for name in solution.raw.robot.get("joints", ()) if name not in known]
    if unknown:
        raise SolutionFileError(f"unknown joint {unknown[0]!r}: expected joints of the scene's "
                                f"robot ({', '.join(known)})", path, key="robot.joints")
    if sol.trajectory:
        width = len(sol.trajectory[0])
        if width != world.n:
            raise SolutionFileError(f"waypoints have {width} joint values for the arm but "
                                    f"the scene's robot has {world.n} "
                                    f"({', '.join(scene_joints)})", path, key="trajectory")
        joints = tuple(sol.robot.get("joints") or ())
        if joints != scene_joints:
            raise SolutionFileError(f"expected the arm joints in the order "
                                    f"{', '.join(scene_joints)}, found {', '.join(joints)}",
                                    path, key="robot.joints")
    tool = sol.robot.get("tool_link")
    if tool is not None and tool != world.tool_link:
        raise SolutionFileError(f"{tool!r} but the scene's robot has tool link "
                                f"{world.tool_link!r}", path, key="robot.tool_link")
    movable = set(world.movable_names)
    for name in sol.objects:
        if name in world.body_names and name not in movable:
            raise SolutionFileError(f"{name!r} is a fixed body of the scene {scene_path}: "
                                    "`objects` holds the movable bodies only", path,
                                    key=f"objects.{name}")
        if name not in movable:
            raise SolutionFileError(f"{name!r} is no body of the scene {scene_path}",
                                    path, key=f"objects.{name}")
    missing = [name for name in world.movable_names if name not in sol.objects]
    if missing:
        raise SolutionFileError(f"no poses for {', '.join(map(repr, missing))}: `objects` needs "
                                f"every movable body of the scene {scene_path}", path,
                                key="objects")
    for i, phase in enumerate(solution.raw.phases):
        if phase.attached is not None and phase.attached not in sol.objects:
            raise SolutionFileError(f"attached object {phase.attached!r} has no poses in "
                                    "`objects`", path, key=f"phases[{i}].attached")


def finger_rows(solution: SolutionFile, world):
    """(N, k) each finger joint's value at each waypoint (World.finger_links' order:
    the joints that mimic the file's follow them), from the file's finger columns;
    None when it gives none."""
    if solution.fingers is None:
        return None
    return np.array([world.finger_values(row) for row in solution.fingers], dtype=float)
