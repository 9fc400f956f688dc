"""Independent feasibility check of a trajectory (what `validate` runs on solution.json).

It trusts nothing the optimizer computed but the trajectory, the phases and the
object poses at phase boundaries: grasps are re-derived from those poses,
collisions are checked at `factor` points per segment (10x the waypoint
resolution by default) with no margin, and every placement is re-measured.
A contact a motion enters or leaves (the object about to be grasped or pushed,
the support under one put down or lifted, the object just released) is
touching, held to the same 1 mm as everything else; only what a carried or
pushed object slides on is left out (the modes' semantics, taken from the
lowered problem). The planar robot holds (or pushes) its object against the
tool's side: that contact is touching too.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize.bodies import REST_TOLERANCE
from tampcli.optimize.closing import closing_words, opened_hand, sweep_contact, sweeps
from tampcli.optimize.path import allowed_contacts
from tampcli.optimize.problem import TrajectoryProblem

PENETRATION = 1e-3  # m: deeper is a collision (FCL's own accuracy is ~1e-4)
RIGID = 2e-3  # m / rad: a held object's drift relative to the tool
LIMIT = 1e-6  # rad / m beyond a joint limit
STILL = 1e-6  # m + rad: a resting object moving less than this between phases has not moved
UPRIGHT = 1e-3  # 1 - cos(tilt) of an object called upright
INSIDE = 1e-3  # m: a footprint or centre this far outside its target is still inside


def _pose(v) -> np.ndarray:
    return transforms.pose_from_xyzquat(v)


def _motion_phases(result) -> list[int]:
    """Indices into result.phases of the phases that move (one per keyframe)."""
    return [i for i, p in enumerate(result.phases) if p.end > p.start]


def verify(problem: TrajectoryProblem, result, factor: int = 10, fingers=None) -> list[str]:
    """Violations in words; empty = feasible. `fingers`: (waypoints, k) finger joint
    values (a solution file's finger columns), else the fingers stay open."""
    if problem.error is not None:
        return [problem.error]
    if result.trajectory is None or not len(result.phases):
        return ["no trajectory"]
    out: list[str] = []
    traj = np.asarray(result.trajectory, dtype=float)
    world = problem.world
    lo, hi = world.lower - LIMIT, world.upper + LIMIT
    bad = np.nonzero(np.any((traj < lo) | (traj > hi), axis=1))[0]
    if len(bad):
        i = int(bad[0])
        j = int(np.argmax(np.maximum(lo - traj[i], traj[i] - hi)))
        out.append(f"waypoint {i}: joint {world.joint_names[j]} = {traj[i, j]:.4f} outside "
                   f"[{world.lower[j]:.4f}, {world.upper[j]:.4f}]")
    moving = _motion_phases(result)
    if len(moving) != problem.n_keyframes:
        return out + [f"expected {problem.n_keyframes} motion phases for the plan, found "
                      f"{len(moving)}"]
    out += _check_objects(problem, result)
    out += [msg for _, msg in failing_motions(problem, result, factor, fingers)]
    out += _closing(problem, result, fingers)
    return out


def _closing(problem: TrajectoryProblem, result, fingers=None) -> list[str]:
    """Where a grasp's fingers close (or a place's open) through something but the
    object (closing.sweep_contact): from the opening the fingers have just before the
    grasp (just after the place) to the object's width across the tool's y axis."""
    if not sweeps(problem):
        return []
    traj = np.asarray(result.trajectory, dtype=float)
    world = problem.world
    hand = None if fingers is None else np.asarray(fingers, dtype=float)
    opened = opened_hand(problem)
    steps = iter(problem.steps)
    out = []
    for pi, phase in enumerate(result.phases):
        if phase.action is None:
            continue
        step = next((s for s in steps if s.name == phase.action), None)
        if step is None:
            break
        if step.kind.fingers is None or step.obj is None or step.obj not in result.object_poses:
            continue
        w = phase.start
        closing = step.kind.fingers is True
        obj = _pose(result.object_poses[step.obj][pi if closing else pi + 1])
        info = problem.bodies[step.obj]
        R = world.tool_pose(traj[w])[:3, :3].T @ obj[:3, :3]
        if info.disk:
            width = 2 * (math.hypot(R[1, 0], R[1, 1]) * info.half[0] + abs(R[1, 2]) * info.half[2])
        else:
            width = 2 * float(np.abs(R[1]) @ np.asarray(info.half[:3]))
        row = min(max(w - 1 if closing else w + 1, 0), len(traj) - 1)
        start = opened if hand is None else hand[row]
        others = {n: _pose(v[pi if closing else pi + 1]) for n, v in result.object_poses.items()
                  if n != step.obj}
        deep = sweep_contact(problem, traj[w], others, step.obj, start, width)
        if deep is not None:
            out.append(closing_words(step.name, deep))
    return out


def failing_motions(problem: TrajectoryProblem, result, factor: int = 10, fingers=None):
    """[(motion index, message)] for collisions found at `factor` points per segment
    (the fingers as `verify` says)."""
    traj = np.asarray(result.trajectory, dtype=float)
    hand = None if fingers is None else np.asarray(fingers, dtype=float)
    world, checker = problem.world, problem.checker
    out = []
    for k, pi in enumerate(_motion_phases(result)):
        phase = result.phases[pi]
        m = problem.motions[k]
        before = {n: _pose(v[pi]) for n, v in result.object_poses.items()}
        held = None
        if phase.attached is not None:
            grasp = transforms.pose_inverse(world.tool_pose(traj[phase.start])) @ before[
                phase.attached]
            held = (phase.attached, grasp)
        others = {n: t for n, t in before.items() if n != phase.attached}
        n_seg = phase.end - phase.start
        taus = np.array([i + j / factor for i in range(n_seg)
                         for j in range(factor + (1 if i == n_seg - 1 else 0))])
        qs = _along(traj, phase.start, n_seg, taus)
        worst = _held_against_tool(problem, m, traj[phase.start], others, held)
        ignores = [allowed_contacts(m)] * len(qs)
        found_all = checker.distances_many(qs, others, held, ignores, 0.0,
                                           fingers=None if hand is None else
                                           _along(hand, phase.start, n_seg, taus))
        # What the motion leaves (in its first segment) or enters (in its last) may be
        # as deep there as at its keyframe, no deeper: a mesh's hull, grown by PyBullet's
        # 1 mm margin, rests 1 mm into its support (blind30 p06: every pick of a mesh
        # failed `collision part vs bench: -0.1 cm` at the pick's waypoint).
        ends = {0: _depths(found_all[0], m.leave_contact),
                n_seg: _depths(found_all[-1], m.enter_contact)}
        for tau, found in zip(taus.tolist(), found_all, strict=True):
            end = ends[0] if tau < 1 else ends[n_seg] if tau > n_seg - 1 else {}
            for c in found:
                if c.distance >= -PENETRATION:
                    continue
                if c.distance >= end.get((c.a, c.b), 0.0) - PENETRATION:
                    continue
                if worst is None or c.distance < worst[0]:
                    worst = (c.distance, tau, c)
        if worst is not None:
            d, tau, c = worst
            out.append((k, f"{_label(problem, k)}: collision {c.a.partition(':')[2]} vs "
                           f"{c.b.partition(':')[2]}: {100 * d:.1f} cm at waypoint "
                           f"{phase.start + tau:.1f}"))
    return out


RESTING_DEPTH = 2.5e-3  # m: the deepest a held object may rest on what it leaves or enters


def _depths(contacts, bodies: frozenset[str]) -> dict[tuple[str, str], float]:
    """(a, b) -> signed distance of the held object's contacts with one of `bodies`
    (names) at a motion's end keyframe, where deeper than the tolerance but no deeper
    than RESTING_DEPTH (a mesh's grown hull on its support); deeper is a collision
    there as anywhere."""
    return {(c.a, c.b): c.distance for c in contacts
            if -RESTING_DEPTH <= c.distance < -PENETRATION
            and "held:" in c.a + c.b
            and (c.a.partition(":")[2] in bodies or c.b.partition(":")[2] in bodies)}


def _along(values: np.ndarray, start: int, n_seg: int, taus: np.ndarray) -> np.ndarray:
    """Rows of `values` (one per waypoint) linear between waypoints, at start + tau."""
    i = np.minimum(taus.astype(int), n_seg - 1)
    s = (taus - i)[:, None]
    return (1 - s) * values[start + i] + s * values[start + i + 1]


def _held_against_tool(problem, m, q, others, held):
    """(distance, tau, contact) of an object held against the tool's side (the planar
    robot's suction or push) when it is deeper in the tool than touching, else None.

    The collision model leaves out what the tool holds against its own rigid group
    (fingers close on a grasped object); held this way it is a contact on a side face,
    and the grip is rigid over the phase, so one configuration measures it.
    """
    if held is None or not problem.planar:
        return None
    checker = problem.checker
    worst = None
    owners = dict.fromkeys(p.owner for p in checker.link_parts
                           if checker.group[p.link] == checker.tool_group)
    for owner in owners:
        c = checker.pair_distance(q, owner, f"held:{held[0]}", others, held)
        if c.distance < -PENETRATION and (worst is None or c.distance < worst[0]):
            worst = (c.distance, 0.0, c)
    return worst


def _label(problem, k) -> str:
    step = problem.step_of_keyframe(k)
    return step.name if problem.motions[k].own else f"motion {k} before {step.name}"


def _check_objects(problem: TrajectoryProblem, result) -> list[str]:
    out = []
    traj = np.asarray(result.trajectory, dtype=float)
    world = problem.world
    poses = {n: [_pose(v) for v in vs] for n, vs in result.object_poses.items()}
    for name in problem.bodies:
        if not problem.bodies[name].fixed and name not in poses:
            out.append(f"object {name}: no poses in the solution")
    if out:
        return out
    n_phases = len(result.phases)
    for name, vs in poses.items():
        if len(vs) != n_phases + 1:
            return [f"object {name}: {len(vs)} poses for {n_phases} phases"]
    regions = {r.name: r for r in problem.scene.regions}
    steps = {s.name: s for s in problem.steps}
    step_iter = iter(problem.steps)
    for pi, phase in enumerate(result.phases):
        for name, vs in poses.items():
            if name == phase.attached and phase.end > phase.start:
                g0 = transforms.pose_inverse(world.tool_pose(traj[phase.start])) @ vs[pi]
                g1 = transforms.pose_inverse(world.tool_pose(traj[phase.end])) @ vs[pi + 1]
                drift = _distance(g0, g1)
                if drift > RIGID:
                    out.append(f"{phase.action or f'motion phase {pi}'}: {name} moves "
                               f"relative to the tool by {100 * drift:.1f} cm")
            elif _distance(vs[pi], vs[pi + 1]) > STILL:
                what = ("jumps" if phase.start == phase.end else "moves but is not attached")
                out.append(f"{phase.action or f'motion phase {pi}'}: {name} {what} "
                           f"({100 * _distance(vs[pi], vs[pi + 1]):.1f} cm)")
        if phase.action is None:
            continue
        step = next(step_iter, None)
        while step is not None and step.name != phase.action:
            step = next(step_iter, None)
        if step is None:
            step = steps.get(phase.action)
        if step is None:
            continue
        out += step.kind.check(StepCheck(problem, traj, phase, pi, poses, regions), step)
    return out


class StepCheck:
    """What a kind's `check` re-measures a step against: the phase that ends with it."""

    def __init__(self, problem, traj, phase, pi: int, poses: dict, regions: dict):
        self.problem = problem
        self.traj = traj
        self.phase = phase
        self.pi = pi  # the phase's index: poses[name][pi] before it, [pi + 1] after
        self.poses = poses
        self.regions = regions

    def tool_start(self) -> np.ndarray:
        return self.problem.world.tool_pose(self.traj[self.phase.start])

    def tool_end(self) -> np.ndarray:
        return self.problem.world.tool_pose(self.traj[self.phase.end])

    def before(self, name: str) -> np.ndarray:
        return self.poses[name][self.pi]

    def after(self, name: str) -> np.ndarray:
        return self.poses[name][self.pi + 1]

    def rest(self, step) -> list[str]:
        """The step's object rests on its support, inside its target."""
        return _check_rest(self.problem, step, self.after(step.obj), self.poses, self.pi + 1,
                           self.regions)


def _distance(a, b) -> float:
    return float(np.linalg.norm(a[:3, 3] - b[:3, 3]) +
                 np.linalg.norm(transforms.rotation_log(a[:3, :3].T @ b[:3, :3])))


def _check_rest(problem, step, pose, poses, boundary, regions) -> list[str]:
    out = []
    info = problem.bodies[step.obj]
    if pose[2, 2] < 1 - UPRIGHT:
        out.append(f"{step.name}: {step.obj} is not upright")
    support = problem.bodies[step.support]
    if step.support in poses:
        s_pose = poses[step.support][boundary]
    else:
        s_pose = transforms.pose_from_xyzquat(problem.scene.body(step.support).pose)
    top = s_pose[2, 3] + support.half[2]
    gap = pose[2, 3] - info.half[2] - top
    if abs(gap) > REST_TOLERANCE:
        out.append(f"{step.name}: {step.obj} is {100 * gap:+.1f} cm off the top of "
                   f"{step.support}")
    if step.target in regions:
        r = regions[step.target]
        corners = _footprint(info, pose)
        outside = max(float(np.max(np.asarray(r.lower) - corners)),
                      float(np.max(corners - np.asarray(r.upper))))
        if outside > INSIDE:
            out.append(f"{step.name}: footprint outside region {r.name} by "
                       f"{100 * outside:.1f} cm")
    elif step.target is not None:
        local = s_pose[:3, :3].T @ (pose[:3, 3] - s_pose[:3, 3])
        if np.any(np.abs(local[:2]) > np.array(support.half[:2]) + INSIDE):
            out.append(f"{step.name}: {step.obj}'s centre is off {step.target}")
    return out


def _footprint(info, pose) -> np.ndarray:
    if info.disk:
        r = info.half[0]
        return pose[:2, 3] + np.array([[-r, -r], [r, r], [-r, r], [r, -r]])
    hx, hy = info.half[0], info.half[1]
    pts = np.array([[a * hx, b * hy, 0.0] for a in (-1, 1) for b in (-1, 1)])
    return (pts @ pose[:3, :3].T + pose[:3, 3])[:, :2]


# ---------------------------------------------------------------- solution files


def verify_solution_file(path, domain_path=None, problem_path=None) -> list[str]:
    """`verify` on a solution.json (scene and modes found as docs/formats.md says).

    `domain_path` / `problem_path` override the files the solution names; each
    may also be an already parsed `ast.Domain` / `ast.Problem`.
    """
    from tampcli import solution as solution_mod
    from tampcli.errors import SolutionFileError
    from tampcli.geometry import scene as scene_mod
    from tampcli.geometry.world import World
    from tampcli.optimize.modes import load_modes
    from tampcli.optimize.problem import lower
    from tampcli.optimize.result import TrajectoryResult
    from tampcli.pddl import ast, parser
    from tampcli.search.plan_text import parse_step
    from tampcli.solution_read import read_solution

    sol = read_solution(path).raw
    if sol.status != "solved":
        return [f"the solution's status is {sol.status}: {sol.reason or 'no reason given'}"]
    scene_path = solution_mod.resolve_input(path, sol.scene)
    if scene_path is None:
        return []  # symbolic solution: nothing geometric to check
    if not scene_path.is_file():
        raise SolutionFileError(f"scene file not found: {scene_path}", str(path), key="scene")
    if isinstance(domain_path, ast.Domain):
        domain = domain_path
        domain_path = Path(domain.path) if domain.path else solution_mod.resolve_input(
            path, sol.domain)
    else:
        domain_path = Path(domain_path) if domain_path else solution_mod.resolve_input(
            path, sol.domain)
        domain = parser.parse_domain_file(str(domain_path))
    if isinstance(problem_path, ast.Problem):
        problem_ast = problem_path
    else:
        problem_path = Path(problem_path) if problem_path else solution_mod.resolve_input(
            path, sol.problem)
        problem_ast = parser.parse_problem_file(str(problem_path))
    modes_path = solution_mod.resolve_input(path, sol.modes) if sol.modes else \
        scene_mod.find_modes(domain_path)
    modes = load_modes(modes_path, domain) if modes_path else {}
    scene = scene_mod.load_scene(scene_path, domain, problem_ast, geometric=False)
    with World(scene, visuals=False) as world:
        if sol.robot.get("joints") and tuple(sol.robot["joints"]) != tuple(world.joint_names):
            return [f"robot joints {sol.robot['joints']} do not match the scene's "
                    f"{list(world.joint_names)}"]
        plan = [parse_step(a, str(path), key=f"plan[{i}]") for i, a in enumerate(sol.plan)]
        problem = lower(plan, scene, modes, world, domain=domain)
        result = TrajectoryResult(
            "solved", "path", problem.names, trajectory=np.array(sol.trajectory, dtype=float),
            phases=sol.phases, object_poses=sol.objects)
        return verify(problem, result)
