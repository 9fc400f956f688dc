"""Inverse kinematics: damped least squares on the numpy chain, within joint limits.

Levenberg-Marquardt steps on the pose error; a joint at a limit that the
step would push further out is frozen for that step (its column removed),
so the others take up the motion instead of the step being clipped away.
Several seeds: the caller's, the start configuration, then random ones.
"""

from __future__ import annotations

import numpy as np

from tampcli.geometry import transforms

MAX_STEP = 0.5  # rad (or m) per joint and iteration


def pose_error(current: np.ndarray, target: np.ndarray) -> np.ndarray:
    """[target - current position; rotation vector taking current to target] (world frame)."""
    dp = target[:3, 3] - current[:3, 3]
    dr = transforms.rotation_log(target[:3, :3] @ current[:3, :3].T)
    return np.concatenate([dp, dr])


class IkMemo:
    """What one World's inverse kinematics has answered, asked again.

    The keyframe guesses of a search ask the same questions over and over:
    every skeleton that starts with the same pick scores the same grips from
    the same configuration (arm-sort: 2,108 calls, 318 distinct targets). An
    answer is kept per (target, seed, settings); a target that every seed
    missed is not tried again from another seed (arm-sort: 190 misses, 45
    targets, 9 s of 25). Answers are copies; `limit` bounds the memory.
    """

    def __init__(self, limit: int = 20000):
        self.limit = limit
        self._answers: dict[bytes, tuple[np.ndarray, float]] = {}
        self._missed: dict[bytes, tuple[np.ndarray, float]] = {}

    def ask(self, world, target, seed, position_only, iterations, restarts, tolerance,
            rng_seed):
        settings = np.array([position_only, iterations, restarts, tolerance], dtype=float)
        where = target.tobytes() + settings.tobytes()
        key = where + (b"" if seed is None else np.asarray(seed, dtype=float).tobytes())
        found = self._answers.get(key) or self._missed.get(where)
        if found is None:
            found = solve_ik(world, target, seed, position_only, iterations, restarts,
                             tolerance, rng_seed)
            if len(self._answers) + len(self._missed) >= self.limit:
                self._answers.clear()
                self._missed.clear()
            self._answers[key] = found
            if found[1] > tolerance and restarts > 0:
                self._missed[where] = found
        return found[0].copy(), found[1]


def solve_ik(world, target, seed, position_only, iterations, restarts, tolerance, rng_seed):
    """Damped least squares from each seed in turn (the caller's, the start, then
    `restarts` random ones) until one comes within `tolerance`; the best otherwise.

    The first seed runs alone (it mostly succeeds: arm-sort, 589 of 661 targets
    reached); the others run side by side as one batch of arrays
    (`_levenberg_marquardt_batch`), with the same answer as one after another:
    the first in order that succeeds. A target no seed reaches (arm-sort: 66 of
    661 targets, 10 seeds of ~40 steps each, 6.2 s of its 7.4 s of IK) costs about
    as many batched steps as its longest seed takes instead of the sum of all."""
    lower, upper = world.lower, world.upper
    rng = np.random.default_rng(rng_seed)
    seeds = []
    if seed is not None:
        seeds.append(np.clip(np.asarray(seed, dtype=float), lower, upper))
    seeds.append(np.clip(world.start, lower, upper))
    finite_lo = np.where(np.isfinite(lower), lower, -np.pi)
    finite_hi = np.where(np.isfinite(upper), upper, np.pi)
    seeds.extend(rng.uniform(finite_lo, finite_hi) for _ in range(restarts))
    rows = slice(0, 3) if position_only else slice(0, 6)
    best_q, best_res = _levenberg_marquardt(world, target, seeds[0], rows, iterations,
                                            tolerance)
    if best_res <= tolerance or len(seeds) == 1:
        return best_q, float(best_res)
    qs, res = _levenberg_marquardt_batch(world, target, np.array(seeds[1:]), rows,
                                         iterations, tolerance)
    i = int(np.argmax(res <= tolerance)) if np.any(res <= tolerance) else int(np.argmin(res))
    if res[i] < best_res:
        best_q, best_res = qs[i], res[i]
    return best_q, float(best_res)


def _levenberg_marquardt(world, target, q, rows, iterations, tolerance):
    lower, upper = world.lower, world.upper
    chain, tool = world.chain, world._tool_index

    def evaluate(q):
        frames = chain.fk_list(q)
        return frames, pose_error(frames[tool], target)[rows]

    frames, err = evaluate(q)
    norm = float(np.linalg.norm(err))
    damping = 1e-2
    stalled = 0
    for _ in range(iterations):
        if norm <= tolerance:
            break
        jac = np.vstack([chain.jacobian_from_frames(frames, tool, frames[tool][:3, 3]),
                         chain.angular_jacobian_from_frames(frames, tool)])[rows]
        step = _step(jac, err, damping)
        blocked = ((q <= lower + 1e-9) & (step < 0)) | ((q >= upper - 1e-9) & (step > 0))
        if blocked.any():
            jac[:, blocked] = 0.0
            step = _step(jac, err, damping)
        step *= min(1.0, MAX_STEP / max(float(np.max(np.abs(step))), 1e-12))
        q_new = np.clip(q + step, lower, upper)
        frames_new, err_new = evaluate(q_new)
        norm_new = float(np.linalg.norm(err_new))
        if norm_new < norm:
            stalled = 0 if norm_new < 0.999 * norm else stalled + 1
            q, frames, err, norm = q_new, frames_new, err_new, norm_new
            damping = max(damping * 0.3, 1e-5)
        else:
            stalled += 1
            damping *= 5.0
        if stalled >= 12 or damping > 1e3:
            break  # a local minimum (often a joint limit): let another seed try
    return q, norm


def _levenberg_marquardt_batch(world, target, qs, rows, iterations, tolerance):
    """`_levenberg_marquardt` from each row of qs (S, n) at once: (final qs, residuals).

    Each seed keeps its own damping and stall count and stops by the same rules;
    the batch stops once the first seed in order that reached `tolerance` has no
    seed before it still running (its answer is then the one a sequential run
    returns), or when every seed has stopped."""
    lower, upper = world.lower, world.upper
    chain, tool = world.chain, world._tool_index
    eye = np.eye(rows.stop - rows.start)

    def evaluate(q):
        frames = chain.fk_batch(q)
        return frames, _pose_errors(frames[:, tool], target)[:, rows]

    qs = np.array(qs, dtype=float)
    frames, err = evaluate(qs)
    norm = np.linalg.norm(err, axis=1)
    damping = np.full(len(qs), 1e-2)
    stalled = np.zeros(len(qs), dtype=int)
    running = norm > tolerance
    for _ in range(iterations):
        reached = np.flatnonzero(norm <= tolerance)
        if not running.any() or (len(reached) and not running[:reached[0]].any()):
            break
        a = np.flatnonzero(running)
        jac = chain.tool_jacobian_batch(frames[a], tool)[:, rows]
        q, d2 = qs[a], (damping[a] ** 2)[:, None, None] * eye
        step = _steps(jac, err[a], d2)
        blocked = ((q <= lower + 1e-9) & (step < 0)) | ((q >= upper - 1e-9) & (step > 0))
        again = np.flatnonzero(blocked.any(axis=1))
        if len(again):
            freed = jac[again] * ~blocked[again][:, None, :]
            step[again] = _steps(freed, err[a[again]], d2[again])
        big = np.maximum(np.abs(step).max(axis=1), 1e-12)
        step *= np.minimum(1.0, MAX_STEP / big)[:, None]
        q_new = np.clip(q + step, lower, upper)
        frames_new, err_new = evaluate(q_new)
        norm_new = np.linalg.norm(err_new, axis=1)
        better = norm_new < norm[a]
        good = a[better]
        stalled[good] = np.where(norm_new[better] < 0.999 * norm[good], 0, stalled[good] + 1)
        qs[good], frames[good], err[good], norm[good] = (
            q_new[better], frames_new[better], err_new[better], norm_new[better])
        damping[good] = np.maximum(damping[good] * 0.3, 1e-5)
        bad = a[~better]
        stalled[bad] += 1
        damping[bad] *= 5.0
        running[a] = (norm[a] > tolerance) & (stalled[a] < 12) & (damping[a] <= 1e3)
    return qs, norm


def _pose_errors(current: np.ndarray, target: np.ndarray) -> np.ndarray:
    """`pose_error` of each of (S, 4, 4) poses: (S, 6)."""
    dp = target[:3, 3] - current[:, :3, 3]
    rel = np.matmul(target[:3, :3], current[:, :3, :3].transpose(0, 2, 1))
    return np.concatenate([dp, transforms.rotation_logs(rel)], axis=1)


def _steps(jac: np.ndarray, err: np.ndarray, damping: np.ndarray) -> np.ndarray:
    """`_step` of each row: jac (S, m, n), err (S, m), damping (S, m, m) (d^2 I)."""
    jt = jac.transpose(0, 2, 1)
    return np.matmul(jt, np.linalg.solve(np.matmul(jac, jt) + damping, err[:, :, None]))[
        :, :, 0]


def _step(jac: np.ndarray, err: np.ndarray, damping: float) -> np.ndarray:
    return jac.T @ np.linalg.solve(jac @ jac.T + damping**2 * np.eye(jac.shape[0]), err)
