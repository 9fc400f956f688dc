"""The geometric half of `validate` on a solution.json, for every shape the format allows.

The verifier (`tampcli.optimize.verify`) expects the trajectory `solve` writes:
for each motion of the lowered plan exactly one moving phase, nothing after
the last action. A checked solution is brought to that shape here, waypoint
indices unchanged where possible:

- the motions of one gap between two actions are one motion (the reader's
  canonical form); a symbolic-only action standing between motions happens at
  the start of the motion around it, since it moves nothing;
- a motion the plan needs but the file leaves out is the robot standing still:
  a one-segment motion between two copies of its waypoint (messages are about
  the file's waypoints again afterwards);
- a move action spanning waypoints absorbs the motions before it;
- the motion after the last action (a retreat) is checked as one more motion.

What the verifier cannot see, because the merging drops it, is checked here:
at each phase boundary inside a merged motion, objects rest where they were
and the held one keeps its grasp. Finger columns are checked against the
fingers' travel, and the collision check puts the fingers where they say.
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import numpy as np

from tampcli import solution as solution_file
from tampcli.errors import SolutionFileError
from tampcli.solution_fit import check_fits_world, finger_rows
from tampcli.solution_read import SolutionFile

RESTING = 1e-6  # m + rad: an object not held must not move at all (as the verifier says)


@dataclasses.dataclass(frozen=True)
class _Span:
    """A phase as the verifier will see it: canonical waypoints, file boundaries."""

    action: str | None
    start: int
    end: int
    attached: str | None
    before: int  # index into the file's pose lists of the boundary before it
    after: int
    stationary: bool = False  # a motion the file leaves out


def geometric_violations(checked: SolutionFile, domain, problem_ast, domain_path) -> list[str]:
    """Violations in words (empty: the trajectory is feasible); a solution that
    does not fit its scene raises SolutionFileError."""
    from tampcli.geometry import scene as scene_mod
    from tampcli.geometry.world import World
    from tampcli.optimize import verify
    from tampcli.optimize.modes import load_modes
    from tampcli.optimize.problem import lower
    from tampcli.search.plan_text import parse_step

    sol, path = checked.canonical, checked.path
    if sol.status != "solved":
        return [f"the solution's status is {sol.status}: {sol.reason or 'no reason given'}"]
    scene_path = solution_file.resolve_input(path, sol.scene)
    if scene_path is None:
        return []  # a symbolic solution: nothing geometric to check
    if not scene_path.is_file():
        raise SolutionFileError(f"scene file not found: {scene_path}", path, key="scene")
    modes_path = solution_file.resolve_input(path, sol.modes) if sol.modes else \
        scene_mod.find_modes(Path(domain_path))
    modes = load_modes(modes_path, domain) if modes_path else {}
    scene = scene_mod.load_scene(scene_path, domain, problem_ast, geometric=False)
    with World(scene, visuals=False) as world:
        check_fits_world(checked, world, scene_path)
        plan = [parse_step(a, str(path), key=f"plan[{i}]") for i, a in enumerate(sol.plan)]
        problem = lower(plan, scene, modes, world, domain=domain)
        if problem.error is not None:
            return [problem.error]
        spans = _spans(checked, problem)
        if spans and spans[-1].action is None:
            problem = _with_retreat(problem, spans[-1], checked, world)
        result, stationary = _result(checked, spans)
        fingers = _fingers(checked, world, stationary)
        found = [_to_file_waypoints(m, stationary)
                 for m in verify.verify(problem, result, fingers=fingers)]
        found += _inside_merged(checked, spans, world)
        found += _finger_travel(checked, world)
    return found


def _spans(checked: SolutionFile, problem) -> list[_Span]:
    """The canonical phases laid out one moving phase per motion of the plan.

    The lowered problem says which motions each step has: an approach (the
    way to a grasp, place or push, carrying what its motion carries) and/or
    its own (a move; a push's pushing). A step with no approach takes the
    motion before it into its own."""
    out: list[_Span] = []
    pending: _Span | None = None  # the motion since the last geometric action
    deferred: list[_Span] = []  # symbolic actions inside that motion
    steps = iter(problem.steps)
    for k, phase in enumerate(checked.canonical.phases):
        before, after = checked.boundaries[k], checked.boundaries[k + 1]
        if phase.action is None:
            if pending is not None and pending.attached == phase.attached:
                pending = dataclasses.replace(pending, end=phase.end, after=after)
            else:
                out += deferred + ([pending] if pending else [])
                pending, deferred = _Span(None, phase.start, phase.end, phase.attached,
                                          before, after), []
            continue
        step = next(steps)
        if not step.kind.geometric:
            if pending is None:
                out.append(_Span(step.name, phase.start, phase.end, phase.attached, before,
                                 after))
            else:
                deferred.append(_Span(step.name, pending.start, pending.start,
                                      phase.attached, pending.before, pending.before))
            continue
        out += deferred
        deferred = []
        approach = next((m for m in problem.motions if m.step == step.index and not m.own), None)
        if approach is None and phase.end > phase.start:
            first = pending or _Span(None, phase.start, phase.start, None, before, before)
            out.append(_Span(step.name, first.start, phase.end, phase.attached, first.before,
                             after))
        else:
            held = approach.attached if approach is not None else step.held_before
            out.append(pending or _Span(None, phase.start, phase.start, held, before, before,
                                        stationary=True))
            out.append(_Span(step.name, phase.start, phase.end, phase.attached, before, after))
        pending = None
    return out + deferred + ([pending] if pending else [])


def _result(checked: SolutionFile, spans: list[_Span]):
    """A TrajectoryResult of the spans, and the final waypoint indices where a
    stationary motion starts."""
    from tampcli.optimize.result import TrajectoryResult
    from tampcli.solution import Phase

    q = checked.canonical.trajectory
    copies: dict[int, int] = {}
    phases, stationary, shift = [], [], 0
    for span in spans:
        start = span.start + shift
        if span.stationary:
            copies[span.start] = copies.get(span.start, 0) + 1
            stationary.append(start)
            shift += 1
            end = start + 1
        else:
            end = span.end + shift
        phases.append(Phase(span.action, start, end, span.attached))
    rows = [q[i] for i in range(len(q)) for _ in range(1 + copies.get(i, 0))]
    raw = checked.raw.objects
    poses = {name: [vs[0]] + [vs[span.after] for span in spans] for name, vs in raw.items()}
    return TrajectoryResult("solved", "path", tuple(s.action for s in spans if s.action),
                            trajectory=np.array(rows, dtype=float), phases=tuple(phases),
                            object_poses=poses), stationary


def _fingers(checked: SolutionFile, world, stationary: list[int]):
    """The file's finger columns (None: none given) on `_result`'s waypoints, every
    finger joint's value (solution_fit.finger_rows): a stationary motion's copied
    waypoint keeps its fingers."""
    found = finger_rows(checked, world)
    if found is None:
        return None
    rows = list(found)
    for at in stationary:  # ascending, each already shifted by the copies before it
        rows.insert(at, rows[at])
    return np.array(rows, dtype=float)


_WAYPOINT = re.compile(r"waypoint (\d+(?:\.\d+)?)")


def _to_file_waypoints(message: str, stationary: list[int]) -> str:
    """The verifier's waypoint numbers are of the trajectory with copies in it."""
    if not stationary:
        return message

    def back(match) -> str:
        x = float(match.group(1))
        x -= sum(min(max(x - p, 0.0), 1.0) for p in stationary)
        return f"waypoint {x:.1f}" if "." in match.group(1) else f"waypoint {round(x)}"

    return _WAYPOINT.sub(back, message)


def _with_retreat(problem, span: _Span, checked: SolutionFile, world):
    """The lowered problem with one more motion: the retreat after the last action.

    It may leave what the last action touched, as the motion after it would in
    the plan (what the last grasp lifted off, what the last place or push let
    go of); a planar robot's load slides on what it stands on."""
    from tampcli.optimize.bodies import REST_TOLERANCE
    from tampcli.optimize.kinds import MOTION
    from tampcli.optimize.problem import MotionPhase, Step

    support, touched = dict(problem.start_supports), frozenset()
    for step in problem.steps:
        if not step.kind.geometric:
            continue
        if step.kind.places:
            touched = frozenset({step.obj})
            support[step.obj] = step.support
        elif step.held_after is not None and step.held_after != step.held_before:
            touched = frozenset({support.get(step.obj)} - {None})  # what it lifted it off
            support[step.obj] = None
        else:
            touched = frozenset()
    sliding: frozenset[str] = frozenset()
    if problem.planar and span.attached is not None:
        held = problem.bodies[span.attached]
        bottom = checked.raw.objects[span.attached][span.before][2] - held.half[2]
        sliding = frozenset(n for n, b in problem.bodies.items()
                            if n != span.attached and abs(b.top - bottom) <= REST_TOLERANCE)
    last = problem.steps[-1].name if problem.steps else None
    step = Step(len(problem.steps), f"the motion after {last}" if last else "the motion",
                MOTION)
    motion = MotionPhase(len(problem.motions), step.index, span.attached, None,
                         "carry" if span.attached else "free", frozenset(), touched, sliding)
    return dataclasses.replace(problem, steps=problem.steps + (step,),
                               motions=problem.motions + (motion,))


def _inside_merged(checked: SolutionFile, spans: list[_Span], world) -> list[str]:
    """Poses at the file's boundaries that fall inside one merged motion."""
    from tampcli.geometry import transforms
    from tampcli.optimize.verify import RIGID

    raw = checked.raw
    q = np.asarray(checked.canonical.trajectory, dtype=float)
    out = []
    for span in spans:
        for b in range(span.before + 1, span.after):
            at = raw.phases[b - 1].end  # the waypoint of boundary b
            for name, poses in raw.objects.items():
                p0 = transforms.pose_from_xyzquat(poses[span.before])
                pb = transforms.pose_from_xyzquat(poses[b])
                if name == span.attached:
                    p0 = transforms.pose_inverse(world.tool_pose(q[span.start])) @ p0
                    pb = transforms.pose_inverse(world.tool_pose(q[at])) @ pb
                    limit, what = RIGID, "moves relative to the tool"
                else:
                    limit, what = RESTING, "moves but is not attached"
                gap = _distance(p0, pb)
                if gap > limit:
                    out.append(f"phases[{b - 1}] (waypoint {at}): {name} {what} "
                               f"({100 * gap:.1f} cm)")
    return out


def _distance(a, b) -> float:
    from tampcli.geometry import transforms

    return float(np.linalg.norm(a[:3, 3] - b[:3, 3])
                 + np.linalg.norm(transforms.rotation_log(a[:3, :3].T @ b[:3, :3])))


def _finger_travel(checked: SolutionFile, world) -> list[str]:
    """Finger joint values within their travel, open to closed (World.finger_range)."""
    from tampcli.optimize.verify import LIMIT

    if checked.fingers is None:
        return []
    values = np.asarray(checked.fingers, dtype=float)
    travel = np.array([sorted(r) for r in world.finger_range], dtype=float)
    bad = np.argwhere((values < travel[:, 0] - LIMIT) | (values > travel[:, 1] + LIMIT))
    if not len(bad):
        return []
    i, j = (int(v) for v in bad[0])
    lo, hi = travel[j]
    return [f"waypoint {i}: finger joint {world.finger_names[j]} = {values[i, j]:.4f} outside "
            f"[{lo:g}, {hi:g}]"]
