"""Inverse kinematics by damped least squares on the numpy chain, with restarts."""

from __future__ import annotations

import numpy as np

from tampcli.geometry import transforms


def pose_error(current: np.ndarray, target: np.ndarray) -> np.ndarray:
    """[target - current position; rotation vector taking current to target] (world frame)."""
    dp = target[:3, 3] - current[:3, 3]
    dr = transforms.rotation_log(target[:3, :3] @ current[:3, :3].T)
    return np.concatenate([dp, dr])


def solve_ik(world, target, seed, position_only, iterations, restarts, tolerance, rng_seed):
    lower, upper = world.lower, world.upper
    rng = np.random.default_rng(rng_seed)
    seeds = []
    if seed is not None:
        seeds.append(np.clip(np.asarray(seed, dtype=float), lower, upper))
    seeds.append(np.clip(world.start, lower, upper))
    finite_lo = np.where(np.isfinite(lower), lower, -np.pi)
    finite_hi = np.where(np.isfinite(upper), upper, np.pi)
    for _ in range(restarts):
        seeds.append(rng.uniform(finite_lo, finite_hi))
    best_q, best_res = seeds[0], np.inf
    rows = slice(0, 3) if position_only else slice(0, 6)
    for q0 in seeds:
        q, res = _dls(world, target, q0, rows, iterations, tolerance)
        if res < best_res:
            best_q, best_res = q, res
        if best_res <= tolerance:
            break
    return best_q, float(best_res)


def _dls(world, target, q, rows, iterations, tolerance):
    lower, upper = world.lower, world.upper
    chain, tool = world.chain, world._tool_index
    damping = 1e-2
    q = q.copy()
    err = None
    for _ in range(iterations):
        frames = chain.fk_list(q)
        err = pose_error(frames[tool], target)[rows]
        norm = float(np.linalg.norm(err))
        if norm <= tolerance:
            return q, norm
        jac = np.vstack([chain.jacobian_from_frames(frames, tool, frames[tool][:3, 3]),
                         chain.angular_jacobian_from_frames(frames, tool)])[rows]
        # Joints at a limit and pushed outward are frozen for this step.
        step = jac.T @ np.linalg.solve(jac @ jac.T + damping**2 * np.eye(jac.shape[0]), err)
        scale = min(1.0, 0.5 / max(np.max(np.abs(step)), 1e-12))
        q_new = np.clip(q + scale * step, lower, upper)
        frames_new = chain.fk_list(q_new)
        new_norm = float(np.linalg.norm(pose_error(frames_new[tool], target)[rows]))
        if new_norm < norm:
            q = q_new
            damping = max(damping * 0.5, 1e-4)
        else:
            damping = min(damping * 4.0, 1.0)
            if damping >= 1.0 and new_norm >= norm:
                break
    frames = chain.fk_list(q)
    return q, float(np.linalg.norm(pose_error(frames[tool], target)[rows]))
