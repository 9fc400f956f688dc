"""The stage driver: one skeleton, one stage -> TrajectoryResult.

final     -> one small NLP over the placements (no robot);
keyframes -> the final NLP (for placements), IK keyframes, one NLP over keyframes;
path      -> keyframes (unless `warm` has them for this skeleton), then one NLP per
             motion phase with its two keyframes fixed, solved by the options'
             backend (backends.py; the other stages' NLPs are SLSQP's); nothing is
             called solved before `verify` passes at 10x the waypoint resolution.
"""

from __future__ import annotations

import dataclasses
import math
import time

import numpy as np

from tampcli.optimize import verify as verify_mod
from tampcli.optimize.assemble import assemble, walk
from tampcli.optimize.backends import BACKENDS, Slsqp
from tampcli.optimize.final_starts import starts
from tampcli.optimize.grips import Kinematics, SideGrip
from tampcli.optimize.init import keyframe_guess
from tampcli.optimize.layout import grip_block, keyframe_block
from tampcli.optimize.motion import solve_motion
from tampcli.optimize.nlp import FEASIBILITY, violation_at
from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.problem import TrajectoryProblem
from tampcli.optimize.result import STAGES, TrajectoryResult
from tampcli.optimize.stages import final_layout, final_rows, keyframe_layout, keyframe_rows
from tampcli.optimize.values import Keyframes, placement_blocks, placements_from_blocks
from tampcli.optimize.world_state import grip_of, reach_of

GRIP_BOUND = 4 * math.pi
RETRY_JITTER = 0.4  # rad: IK seed perturbation of the second keyframe attempt
# Path solves per skeleton that `verify` judges: each round after the first samples the
# failing motions twice as finely (3, 7, 15 points a segment by default); a motion that
# ends in a narrow slot can dip into a wall between 7.
VERIFY_ROUNDS = 3
FACE_SAME = 0.05  # rad: a contact angle this close to a face's middle is at that face
FIXED_GRIP = 1e-6  # rad: the bounds' half width around a grip parameter kept fixed


class _Run:
    """Per-call bookkeeping: deadline, counters, the checker and kinematics."""

    def __init__(self, problem: TrajectoryProblem, stage: str):
        self.problem = problem
        self.stage = stage
        self.t0 = time.perf_counter()
        self.deadline = self.t0 + problem.options.time_limit
        self.iterations = 0
        self.nlp_solves = 0
        self.kin = Kinematics(problem.world)
        self.checker = problem.checker
        self.start = np.asarray(problem.world.start, dtype=float)
        self.rng = np.random.default_rng(problem.options.seed)

    def result(self, status: str, **fields) -> TrajectoryResult:
        fields.setdefault("bound_kind", "heuristic" if self.stage != "final" else "proved")
        return TrajectoryResult(status=status, stage=self.stage, names=self.problem.names,
                                iterations=self.iterations, nlp_solves=self.nlp_solves,
                                seconds=time.perf_counter() - self.t0, **fields)

    def nlp(self, evaluate, layout, x0, bounds, backend=None):
        """One counted solve by `backend` (SLSQP when None: the final and keyframe NLPs)."""
        out = (backend or Slsqp()).solve(evaluate, layout, x0, bounds,
                                         self.problem.options.max_iterations, self.deadline)
        self.iterations += out.iterations
        self.nlp_solves += 1
        return out

    def path_nlp(self, evaluate, layout, x0, bounds):
        """A motion's NLP, by the options' backend (`nlp`)."""
        return self.nlp(evaluate, layout, x0, bounds, BACKENDS[self.problem.options.nlp])


def solve(problem: TrajectoryProblem, stage: str, warm: TrajectoryResult | None = None,
          options: OptimizeOptions | None = None) -> TrajectoryResult:
    """Solve `stage` of the skeleton's NLP; never raises for a failed solve."""
    if stage not in STAGES:
        raise ValueError(f"stage must be one of {', '.join(STAGES)}, got {stage!r}")
    if options is not None and options != problem.options:
        problem = dataclasses.replace(problem, options=options)
    run = _Run(problem, stage)
    if problem.error is not None:
        return run.result("infeasible", worst_constraint=problem.error, proved=True,
                          bound_kind="proved", violation=math.inf)
    try:
        if stage == "final":
            return _final(run)
        if stage == "keyframes":
            return _keyframes(run, warm)
        return _path(run, warm)
    except np.linalg.LinAlgError as err:
        return run.result("infeasible", worst_constraint=f"numerical failure: {err}",
                          violation=math.inf)


# ---------------------------------------------------------------- final


def _too_small(problem) -> str | None:
    """An object whose footprint fits its target region in no orientation (proved)."""
    regions = {r.name: r for r in problem.scene.regions}
    for step in problem.steps:
        if step.kind.places and step.target in regions:
            w, h = regions[step.target].size
            info = problem.bodies[step.obj]
            a, b = 2 * info.half[0], 2 * info.half[1]
            if not ((a <= w and b <= h) or (b <= w and a <= h)):
                return (f"{step.name}: {step.obj} ({100 * a:.0f} x {100 * b:.0f} cm) does not "
                        f"fit region {step.target} ({100 * w:.0f} x {100 * h:.0f} cm)")
    return None


def _beyond_reach(problem) -> str | None:
    """A target region no point of which the Panda's tool can come near (proved).

    The Panda's reach ball (world_state.reach_of: the stretched arm from the
    shoulder) bounds where the tool can be; the tool holds the object inside
    the object's bounding sphere, so a region farther from the ball than that
    radius cannot receive it. Other arms' reach is sampled, not a bound: no
    proof for them.
    """
    if problem.planar or problem.scene.robot.model != "panda":
        return None
    centre, reach = reach_of(problem)
    regions = {r.name: r for r in problem.scene.regions}
    for step in problem.steps:
        if step.kind.places and step.target in regions:
            region = regions[step.target]
            info = problem.bodies[step.obj]
            nearest = np.clip(centre[:2], region.lower, region.upper)
            gap = math.hypot(*(nearest - centre[:2]), step.rest_z - centre[2])
            slack = math.sqrt(info.half[0] ** 2 + info.half[1] ** 2 + info.half[2] ** 2)
            if gap > reach + slack:
                return (f"{step.name}: region {step.target} is {100 * (gap - reach):.0f} cm "
                        f"beyond the arm's reach ({reach:.2f} m from the shoulder)")
    return None


def _placements(run: _Run):
    """Run the final NLP from each of final_starts.starts until one solves; returns
    (outcome or None when there is nothing to place, values). Its outcome depends on
    the skeleton alone (no warm start from another skeleton: see final_starts)."""
    problem = run.problem
    layout = final_layout(problem)
    if layout.size == 0:
        return None, {}
    bounds = [(-1e3, 1e3)] * layout.size
    best = None
    for start in starts(problem):
        placements, origins = start(problem)
        out = run.nlp(lambda x, origins=origins: final_rows(problem, layout.unpack(x), origins),
                      layout, layout.pack(placement_blocks(placements)), bounds)
        if best is None or out.status == "solved" or out.violation < best[0].violation:
            best = (out, placements)
        if out.status == "solved" or time.perf_counter() > run.deadline:
            break
    out, placements = best
    return out, placements_from_blocks(layout.unpack(out.x), placements)


def _final(run: _Run) -> TrajectoryResult:
    why = _too_small(run.problem) or _beyond_reach(run.problem)
    if why:
        return run.result("infeasible", worst_constraint=why, proved=True, violation=math.inf)
    out, placements = _placements(run)
    if out is None:
        return run.result("solved", cost=0.0)
    if out.status != "solved":
        return run.result(out.status, violation=out.violation, worst_constraint=out.worst,
                          placements=placements)
    return run.result("solved", cost=0.0, violation=out.violation, placements=placements,
                      kkt_residual=out.kkt)


# ---------------------------------------------------------------- keyframes


def _shares_prefix(problem, warm) -> bool:
    return (warm is not None and warm.keyframes and len(warm.names) <= len(problem.names)
            and tuple(problem.names[:len(warm.names)]) == tuple(warm.names))


def _keyframes(run: _Run, warm) -> TrajectoryResult:
    """The keyframe NLP; where it fails, again with the planar suction grips kept at
    the middle of each face (`_face_grips`: a peg pushed into a socket by its back face)."""
    result = _keyframes_with(run, warm)
    for grips in _face_grips(run.problem, result):
        if result.solved or result.proved or time.perf_counter() > run.deadline:
            break
        again = _keyframes_with(run, warm, grips)
        result = again if again.solved else result
    return result


def _keyframes_with(run: _Run, warm, grips: dict[int, float] | None = None
                    ) -> TrajectoryResult:
    """`grips`: step -> a grip parameter the NLP keeps (the NLP's choice otherwise)."""
    problem = run.problem
    why = _too_small(problem) or _beyond_reach(problem)
    if why:
        return run.result("infeasible", worst_constraint=why, proved=True, violation=math.inf)
    have = warm is not None and warm.placements and all(
        s.index in warm.placements for s in problem.steps if s.kind.places)
    if have and warm.names == problem.names:
        placements = warm.placements
    else:
        out, placements = _placements(run)
        if out is not None and out.status != "solved":
            return run.result(out.status, violation=out.violation,
                              worst_constraint=f"placements: {out.worst}")
    layout = keyframe_layout(problem)
    if layout.size == 0:  # symbolic actions only: nothing moves
        return run.result("solved", cost=0.0, placements=placements)
    world = problem.world
    bounds = []
    joints = {keyframe_block(k) for k in range(problem.n_keyframes)}
    fixed = {grip_block(s): t for s, t in (grips or {}).items()}
    for name, _size in layout.blocks:
        if name in joints:
            bounds.extend(zip(world.lower, world.upper, strict=True))
        elif name in fixed:
            bounds.append((fixed[name] - FIXED_GRIP, fixed[name] + FIXED_GRIP))
        else:
            bounds.append((-GRIP_BOUND, GRIP_BOUND))
    best = None
    for attempt in range(2):
        guess, choices = keyframe_guess(problem, placements, run.start, run.rng,
                                        jitter=RETRY_JITTER if attempt else 0.0)
        if attempt == 0 and _shares_prefix(problem, warm):
            choices.update(warm.choices)
            guess = guess.warmed(warm.keyframes)
        if grips:
            guess = Keyframes(guess.q, {**guess.grip, **grips})

        def evaluate(x, choices=choices):
            return keyframe_rows(problem, layout.unpack(x), choices, run.kin, run.checker,
                                 run.start)

        out = run.nlp(evaluate, layout, layout.pack(guess.blocks()), bounds)
        if best is None or (out.status == "solved") or out.violation < best[0].violation:
            best = (out, choices)
        if out.status == "solved" or time.perf_counter() > run.deadline:
            break
    out, choices = best
    if out.status != "solved" and time.perf_counter() < run.deadline:
        out = _tight_keyframes(run, layout, bounds, out, choices)
    kf = Keyframes.from_blocks(layout.unpack(out.x), problem.n_keyframes, problem.grip_params)
    T = problem.options.waypoints
    qs = [run.start, *kf.q]
    phase_costs = tuple(float(np.sum((b - a) ** 2)) / T for a, b in zip(qs, qs[1:], strict=False))
    if out.status != "solved":
        return run.result(out.status, violation=out.violation, worst_constraint=out.worst,
                          keyframes=kf, choices=choices, placements=placements)
    if out.stopped == "time":
        # Feasible but far from converged: its cost would be a meaningless bound.
        return run.result("limit", violation=out.violation, keyframes=kf, choices=choices,
                          placements=placements, worst_constraint="time limit reached before "
                          "the keyframe NLP converged")
    return run.result("solved", cost=out.cost, phase_costs=phase_costs,
                      violation=out.violation, kkt_residual=out.kkt, keyframes=kf,
                      choices=choices, placements=placements)


def _tight_keyframes(run: _Run, layout, bounds, out, choices):
    """The keyframe NLP again with `tight_margin`, from where it failed, when the
    margin is part of what it violates there (a slot narrower than twice the
    margin); else, or when that fails too, `out`."""
    problem = run.problem
    opts = problem.options
    if opts.tight_margin >= opts.margin:
        return out
    tight = dataclasses.replace(problem, options=dataclasses.replace(
        opts, margin=opts.tight_margin))

    def evaluate(x):
        return keyframe_rows(tight, layout.unpack(x), choices, run.kin, run.checker, run.start)

    if violation_at(evaluate, layout, out.x) >= out.violation - FEASIBILITY:
        return out
    retry = run.nlp(evaluate, layout, out.x, bounds)
    return retry if retry.status == "solved" or retry.violation < out.violation else out


# ---------------------------------------------------------------- path


def _path(run: _Run, warm) -> TrajectoryResult:
    problem = run.problem
    if (warm is not None and warm.solved and warm.stage in ("keyframes", "path")
            and warm.names == problem.names and warm.keyframes):
        kfr = warm
    else:
        run.stage = "keyframes"
        kfr = _keyframes(run, warm)
        run.stage = "path"
        if not kfr.solved:
            return run.result(kfr.status, violation=kfr.violation,
                              worst_constraint=kfr.worst_constraint, proved=kfr.proved)
    # A suction grip off a face's middle first gets that face (a carry in line with
    # the disk), then the NLP's own angle, then the other faces.
    faces = list(_face_grips(problem, kfr))
    result = None
    for grips in faces[:1] + [None] + faces[1:]:
        if result is not None and (result.solved or time.perf_counter() > run.deadline):
            break
        start = kfr
        if grips is not None:
            run.stage = "keyframes"
            start = _keyframes_with(run, warm, grips)
            run.stage = "path"
        if start.solved:
            found = _path_through(run, start)
            result = found if result is None or found.solved else result
    return result


def _face_grips(problem, kfr):
    """Other planar suction grips, kept fixed: the rim at the middle of each face.

    The keyframe NLP takes the cheapest contact angle near its guess; a carry through a
    passage may need the object in line with the disk (robust-planar p03: beside
    it, disk and block span 18 cm of an 11 cm doorway), which only the path
    stage finds out. Nearest faces first; the face the angle is at already is
    not tried again.
    """
    steps = {s.index: s for s in problem.steps}
    sides = {}
    if not kfr.keyframes:
        return
    for index, t in kfr.keyframes.grip.items():
        grip = grip_of(problem, steps[index], kfr.choices)
        if isinstance(grip, SideGrip) and grip.half is not None:
            faces = [t + _wrap(grip.yaw + j * math.pi / 2 - t) for j in range(4)]
            sides[index] = sorted(faces, key=lambda f, t=t: abs(f - t))
    for j in range(4):
        grips = {i: faces[j] for i, faces in sides.items()}
        if grips and any(abs(f - kfr.keyframes.grip[i]) > FACE_SAME for i, f in grips.items()):
            yield grips


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def _path_through(run: _Run, kfr) -> TrajectoryResult:
    """The path stage through the keyframes of `kfr` (solved)."""
    problem = run.problem
    kf, choices = kfr.keyframes, kfr.choices
    contexts = walk(problem, kf, choices, run.start)
    opts = problem.options
    T = opts.waypoints
    waypoints, kkts = {}, []
    checks = opts.interpolation_checks
    failing: set[int] = set()
    for attempt in range(VERIFY_ROUNDS):
        for ctx in contexts:
            if attempt and ctx.index not in failing:
                continue
            out = solve_motion(run, ctx, T, checks, _phase_label(problem, ctx.index))
            if out.status != "solved":
                label = _phase_label(problem, ctx.index)
                return run.result(out.status, violation=out.violation,
                                  worst_constraint=out.worst or label, keyframes=kf,
                                  choices=choices, placements=kfr.placements)
            waypoints[ctx.index] = out.x.reshape(T - 1, problem.n)
            if out.kkt is not None:
                kkts.append(out.kkt)
        traj, phases, poses, grasps = assemble(problem, run.start, waypoints, contexts)
        result = run.result("solved", cost=float(np.sum(np.diff(traj, axis=0) ** 2)),
                            phase_costs=_phase_costs(traj, T, problem.n_keyframes),
                            kkt_residual=max(kkts) if kkts else None, trajectory=traj,
                            phases=phases, object_poses=poses, keyframes=kf, choices=choices,
                            placements=kfr.placements, grasps=grasps)
        problems = verify_mod.verify(problem, result)
        if not problems:
            return result
        # A collision between the sample points: sample the failing phases finer.
        failing.clear()
        failing.update({i for i, _ in verify_mod.failing_motions(problem, result)}
                       or range(problem.n_keyframes))
        checks = 2 * checks + 1
        if time.perf_counter() > run.deadline:
            break
    return run.result("infeasible", violation=math.inf, worst_constraint=problems[0],
                      keyframes=kf, choices=choices, placements=kfr.placements)


def _phase_costs(traj, T, K):
    d = np.sum(np.diff(traj, axis=0) ** 2, axis=1)
    return tuple(float(np.sum(d[k * T:(k + 1) * T])) for k in range(K))


def _phase_label(problem, k) -> str:
    return f"motion {k} before {problem.step_of_keyframe(k).name}"
