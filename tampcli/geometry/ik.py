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
            self._keep(key, where, found, tolerance, restarts)
        return found[0].copy(), found[1]

    def ask_many(self, world, targets, seeds, rng_seeds, position_only, iterations, restarts,
                 tolerance) -> list[tuple[np.ndarray, float]]:
        """`ask` of each (target, seed, rng_seed) in turn, the same answers; the first
        seeds of the questions not answered before run side by side as one batch
        (`_levenberg_marquardt_batch`, each target its own), and only a target its
        first seed misses goes on to its other seeds, one question at a time.

        The keyframe guess asks a grasp family's grips, and their places, at once
        (kinds/grasp.py); most are reached from the first seed (arm-sort: 589 of
        661 targets)."""
        settings = np.array([position_only, iterations, restarts, tolerance], dtype=float)
        rows = slice(0, 3) if position_only else slice(0, 6)
        targets = [np.asarray(t, dtype=float) for t in targets]
        asked = []
        for target, seed in zip(targets, seeds, strict=True):
            where = target.tobytes() + settings.tobytes()
            asked.append((where, where + (b"" if seed is None else
                                          np.asarray(seed, dtype=float).tobytes())))
        firsts: dict[bytes, int] = {}  # key -> question whose first seed is solved
        for i, (where, key) in enumerate(asked):
            if key not in self._answers and where not in self._missed:
                firsts.setdefault(key, i)
        order, first = list(firsts.values()), {}
        if order:
            starts = np.array([_seed_list(world, seeds[i], 0, None)[0] for i in order])
            qs, res = _levenberg_marquardt_batch(
                world, np.array([targets[i] for i in order], dtype=float), starts, rows,
                iterations, tolerance, starts=np.arange(len(order)))
            first = {asked[i][1]: (qs[j], float(res[j])) for j, i in enumerate(order)}
        tried = self._restarts(world, asked, order, first, targets, seeds, rng_seeds, restarts,
                               rows, iterations, tolerance)
        out = []
        for i, (where, key) in enumerate(asked):
            found = self._answers.get(key) or self._missed.get(where)
            if found is None:
                tries = _seed_list(world, seeds[i], restarts, rng_seeds[i])
                # (the memo cleared at its limit since: asked afresh)
                q, res = first[key] if key in first else _levenberg_marquardt(
                    world, targets[i], tries[0], rows, iterations, tolerance)
                found = _finish(world, targets[i], tries, q, res, rows, iterations, tolerance,
                                tried.get(key))
                self._keep(key, where, found, tolerance, restarts)
            out.append((found[0].copy(), found[1]))
        return out

    @staticmethod
    def _restarts(world, asked, order, first, targets, seeds, rng_seeds, restarts, rows,
                  iterations, tolerance) -> dict:
        """key -> (qs, residuals) of the other seeds of each question its first seed
        missed, all run as one batch (a group per question). Only the first such
        question of a target: asked in turn, a later one with another seed gets its
        miss from the memo, or, where it succeeded, runs its own seeds then."""
        leads, groups, rows_qs, aims = {}, [], [], []
        for i in order:
            where, key = asked[i]
            if first[key][1] <= tolerance or not restarts or where in leads:
                continue
            tries = _seed_list(world, seeds[i], restarts, rng_seeds[i])[1:]
            leads[where] = key
            groups.append(len(rows_qs))
            rows_qs += tries
            aims += [targets[i]] * len(tries)
        if not groups:
            return {}
        qs, res = _levenberg_marquardt_batch(world, np.array(aims), np.array(rows_qs), rows,
                                             iterations, tolerance, starts=groups)
        bounds = [*groups, len(rows_qs)]
        return {key: (qs[a:b], res[a:b])
                for key, a, b in zip(leads.values(), bounds, bounds[1:], strict=False)}

    def _keep(self, key, where, found, tolerance, restarts) -> None:
        if len(self._answers) + len(self._missed) >= self.limit:
            self._answers.clear()
            self._missed.clear()
        self._answers[key] = found
        if found[1] > tolerance and restarts > 0:
            self._missed[where] = found


def solve_ik(world, target, seed, position_only, iterations, restarts, tolerance, rng_seed):
    """Damped least squares from each seed in turn (the caller's, the start, then
    `restarts` random ones) until one comes within `tolerance`; the best otherwise.

    The first seed runs alone (it mostly succeeds: arm-sort, 589 of 661 targets
    reached); the others run side by side as one batch of arrays
    (`_levenberg_marquardt_batch`), with the same answer as one after another:
    the first in order that succeeds. A target no seed reaches (arm-sort: 66 of
    661 targets, 10 seeds of ~40 steps each, 6.2 s of its 7.4 s of IK) costs about
    as many batched steps as its longest seed takes instead of the sum of all."""
    seeds = _seed_list(world, seed, restarts, rng_seed)
    rows = slice(0, 3) if position_only else slice(0, 6)
    first_q, first_res = _levenberg_marquardt(world, target, seeds[0], rows, iterations,
                                              tolerance)
    return _finish(world, target, seeds, first_q, first_res, rows, iterations, tolerance)


def _seed_list(world, seed, restarts, rng_seed) -> list[np.ndarray]:
    """The seeds in the order they are tried: the caller's, the start, then `restarts`
    random ones drawn from `rng_seed`."""
    lower, upper = world.lower, world.upper
    seeds = []
    if seed is not None:
        seeds.append(np.clip(np.asarray(seed, dtype=float), lower, upper))
    seeds.append(np.clip(world.start, lower, upper))
    if restarts:
        rng = np.random.default_rng(rng_seed)
        finite_lo = np.where(np.isfinite(lower), lower, -np.pi)
        finite_hi = np.where(np.isfinite(upper), upper, np.pi)
        seeds.extend(rng.uniform(finite_lo, finite_hi) for _ in range(restarts))
    return seeds


def _finish(world, target, seeds, best_q, best_res, rows, iterations, tolerance,
            tried=None):
    """solve_ik's answer once its first seed gave (best_q, best_res): the other seeds
    run (side by side) only where the first missed; `tried`: their (qs, residuals),
    already run."""
    if best_res <= tolerance or len(seeds) == 1:
        return best_q, float(best_res)
    qs, res = tried if tried is not None else _levenberg_marquardt_batch(
        world, target, np.array(seeds[1:]), rows, iterations, tolerance)
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


def _levenberg_marquardt_batch(world, targets, qs, rows, iterations, tolerance,
                               starts=(0,)):
    """`_levenberg_marquardt` from each row of qs (S, n) at once: (final qs, residuals).

    `targets`: (S, 4, 4), each row's own, or (1, 4, 4), one for all. Each row keeps
    its own damping and stall count and stops by the same rules. The rows come in
    groups (`starts`: the first row of each; one group by default), each the seeds
    of one question tried in turn: a group stops once its first row in order that
    reached `tolerance` has no row before it still running (its answer is then the
    one a sequential run returns), or when all its rows have stopped. Independent
    questions: a group per row."""
    lower, upper = world.lower, world.upper
    chain, tool = world.chain, world._tool_index
    eye = np.eye(rows.stop - rows.start)
    targets = np.asarray(targets, dtype=float).reshape(-1, 4, 4)

    def evaluate(q, which):
        frames = chain.fk_batch(q)
        aim = targets if len(targets) == 1 else targets[which]
        return frames, _pose_errors(frames[:, tool], aim)[:, rows]

    qs = np.array(qs, dtype=float)
    frames, err = evaluate(qs, slice(None))
    norm = np.linalg.norm(err, axis=1)
    damping = np.full(len(qs), 1e-2)
    stalled = np.zeros(len(qs), dtype=int)
    running = norm > tolerance
    starts = np.asarray(starts, dtype=int)
    group = np.repeat(np.arange(len(starts)), np.diff(np.append(starts, len(qs))))
    index = np.arange(len(qs))
    for _ in range(iterations):
        # A group whose first success in order has no row before it running is done.
        first = np.minimum.reduceat(np.where(norm <= tolerance, index, len(qs)), starts)
        waiting = np.logical_or.reduceat(running & (index < first[group]), starts)
        running &= ~((first < len(qs)) & ~waiting)[group]
        if not running.any():
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
        frames_new, err_new = evaluate(q_new, a)
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
    """`pose_error` of each of (S, 4, 4) poses against `target`: (4, 4), (1, 4, 4) or
    (S, 4, 4), one per pose: (S, 6)."""
    dp = target[..., :3, 3] - current[:, :3, 3]
    rel = np.matmul(target[..., :3, :3], current[:, :3, :3].transpose(0, 2, 1))
    return np.concatenate([dp, transforms.rotation_logs(rel)], axis=1)


def _steps(jac: np.ndarray, err: np.ndarray, damping: np.ndarray) -> np.ndarray:
    """`_step` of each row: jac (S, m, n), err (S, m), damping (S, m, m) (d^2 I)."""
    jt = jac.transpose(0, 2, 1)
    return np.matmul(jt, np.linalg.solve(np.matmul(jac, jt) + damping, err[:, :, None]))[
        :, :, 0]


def _step(jac: np.ndarray, err: np.ndarray, damping: float) -> np.ndarray:
    return jac.T @ np.linalg.solve(jac @ jac.T + damping**2 * np.eye(jac.shape[0]), err)
