"""An independent checker of tampcli solutions, for tests only.

It shares no code with tampcli: it reads scene.toml (tomllib), the problem's
goal (a small s-expression reader) and solution.json (json) itself, builds its
own PyBullet DIRECT scene and asks PyBullet's getClosestPoints. It opens its
own client, which the product's rule "PyBullet only inside World" does not
cover: the point is a second opinion that does not trust World.

Replay. The trajectory is replayed at 10x the waypoint resolution (linear
interpolation between consecutive waypoints). Movable objects stand at the
pose solution.json gives at the start of each phase; the object a phase says
is `attached` moves with the hand, at the pose relative to the hand it had
when it became attached. Panda fingers: the given values when the finger
joints are among the solution's joints; otherwise fully open (0.04), and
while an object is attached, closed until they touch it.

Rules (a penetration is a signed distance below -1 mm):

1. collision -- at every sample: robot links against every body; the held
   object against every other body; movable objects against everything at
   every phase boundary; robot self-collision between non-adjacent links.
   Not collisions: a grasped object (it became attached at an instantaneous
   action) against the Panda's hand and fingers, which close on it; the
   robot's base link against the body it stands on (resting contact);
   adjacent links (parent and child, a link without geometry on a fixed
   joint merged into its parent) and the two fingers (they close on each
   other with nothing between them). A pushed object and the planar robot's
   suction grasp are contacts on a side face: touching, so checked like any
   pair (a push's pose is set by an action that spans a motion). Resting
   contact is distance about 0, which the 1 mm tolerance admits (for a mesh,
   whose hull PyBullet grows by a 1 mm margin, 2 mm); a body sunk deeper
   into its support is a collision. Mesh and URDF files are looked for
   beside the scene, then in pybullet_data; `scale` is one number or three. At a grasp, prismatic
   fingers (Panda, KUKA) closing from their opening just before it to the
   object, 2 mm steps, pass into nothing else.
2. attachment -- at each boundary of a phase with an attached object, the
   pose solution.json gives equals hand pose x relative pose (1 mm, 1 deg);
   an object not attached does not move across a phase (same tolerances).
   A pushed object keeps its height and stays upright (1 mm, 1 deg).
3. support -- at each boundary, every object not held rests on the top face
   of some body (its bottom within 5 mm of that face, its centre over it).
4. goal -- every goal atom (pred x y) with x a movable object and y a region
   (x and y: the object and target arguments of the place or push action that
   adds pred, where the domain and modes files say so; else pred's first two):
   x's whole footprint (its projection on the region's support) lies inside
   the region's rectangle (1 mm tolerance) and its bottom is within 5 mm of
   the support's top face; with y a body: the same against y's top face (a
   cylinder's round top exactly: the ring of x's footprint within its radius).
   `and` needs every part, `or` any one; other goal atoms are symbolic.
5. limits -- every waypoint within the URDF joint limits.

    python -m tests.robustness.checker SOLUTION.json [--scene S] [--problem P]
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import tomllib

from tests.robustness.bullet_scene import FINGERS, Replay, matrix, pose_error

TOL_POS, TOL_ANG, TOL_REST, SUB = 1e-3, math.radians(1.0), 5e-3, 10


@dataclass(frozen=True)
class Violation:
    kind: str      # collision | attachment | support | goal | limits
    where: str
    message: str

    def __str__(self) -> str:
        return f"{self.kind}: {self.where}: {self.message}"


def _resolve(name: str, beside: Path) -> Path:
    for cand in (beside.parent / name, Path(name)):
        if cand.exists():
            return cand
    raise FileNotFoundError(name)


def _sexp(text: str):
    text = "\n".join(line.split(";", 1)[0] for line in text.lower().splitlines())
    stack: list[list] = [[]]
    for tok in text.replace("(", " ( ").replace(")", " ) ").split():
        if tok == "(":
            stack.append([])
        elif tok == ")":
            done = stack.pop()
            stack[-1].append(done)
        else:
            stack[-1].append(tok)
    return stack[0][0]


def read_goal(problem: Path):
    for part in _sexp(problem.read_text()):
        if isinstance(part, list) and part and part[0] == ":goal":
            return part[1]
    return ["and"]


def _samples(traj: np.ndarray, s: int, e: int):
    """(fractional waypoint index, configuration) at SUB samples per segment."""
    yield float(s), traj[s]
    for i in range(s, e):
        for j in range(1, SUB + 1):
            t = j / SUB
            yield i + t, (1 - t) * traj[i] + t * traj[i + 1]


def _limits(rp: Replay, names: list[str], traj: np.ndarray) -> list[Violation]:
    out = []
    for c, n in enumerate(names):
        if n in rp.limits:
            lo, hi = rp.limits[n]
            bad = np.flatnonzero((traj[:, c] < lo - 1e-6) | (traj[:, c] > hi + 1e-6))
            if bad.size:
                out.append(Violation("limits", f"waypoint {bad[0]}",
                                     f"{n} = {traj[bad[0], c]:.4f} outside [{lo}, {hi}]"))
    return out


def goal_roles(domain: Path, modes: Path) -> dict[str, tuple[int, int]]:
    """predicate -> (argument of the object, argument of where it rests) for the
    predicates a place (`on`) or push (`to`) action of the modes file adds: the goal
    atom (capped jar lid) of a `cap` that puts ?l on ?j is lid on jar, not the
    first argument on the second. Read from the domain's own text."""
    table = tomllib.loads(modes.read_text())
    roles: dict[str, tuple[int, int]] = {}
    for part in _sexp(domain.read_text()):
        if not (isinstance(part, list) and len(part) > 1 and part[0] == ":action"):
            continue
        spec = table.get(part[1])
        if not isinstance(spec, dict) or spec.get("mode") not in ("place", "push"):
            continue
        obj, target = spec.get("object"), spec.get("on") or spec.get("to")
        fields = dict(zip(part[2::2], part[3::2], strict=False))
        effect = fields.get(":effect", [])
        atoms = effect[1:] if effect and effect[0] == "and" else [effect]
        for atom in atoms:
            if atom and isinstance(atom[0], str) and atom[0] not in ("not", "forall", "when") \
                    and obj in atom[1:] and target in atom[1:]:
                roles.setdefault(atom[0], (atom.index(obj) - 1, atom.index(target) - 1))
    return roles


def goal_failures(rp: Replay, goal, movable: list[str],
                  roles: dict[str, tuple[int, int]] | None = None) -> list[str]:
    """Messages for the goal atoms that do not hold geometrically. `roles`
    (goal_roles) says which argument rests on which; without it, (pred x y)."""
    if not goal or not isinstance(goal[0], str):
        return []
    if goal[0] == "and":
        return [m for part in goal[1:] for m in goal_failures(rp, part, movable, roles)]
    if goal[0] == "or":
        parts = [goal_failures(rp, part, movable, roles) for part in goal[1:]]
        return [] if any(not p for p in parts) else ["no part of (or ...) holds: " + parts[0][0]]
    if not all(isinstance(g, str) for g in goal):
        return []
    i, j = (roles or {}).get(goal[0], (0, 1))
    args = goal[1:]
    if max(i, j) >= len(args) or (goal[0] not in (roles or {}) and len(args) != 2):
        return []
    x, y = args[i], args[j]
    if x not in movable:
        return []
    pts, bottom = rp.footprint(x)
    if y in rp.regions:
        reg = rp.regions[y]
        frame, half, top = rp.top_face(reg["on"])
        frame = np.eye(4)
        frame[:2, 3] = reg["center"]
        half = np.array(reg["size"]) / 2
    elif y in rp.bodies:
        frame, half, top = rp.top_face(y)
    else:
        return []
    if y in rp.bodies and rp.info[y]["shape"] == "cylinder":  # its round top, exactly
        over = float(np.max(np.linalg.norm(pts - frame[:2, 3], axis=1))) - rp.info[y]["size"][0]
    else:
        local = (pts - frame[:2, 3]) @ frame[:2, :2]
        over = float(np.max(np.abs(local) - half))
    msgs = []
    if over > TOL_POS:
        msgs.append(f"({' '.join(goal)}): {x}'s footprint sticks out of {y} by {over * 1000:.1f} mm")
    if abs(bottom - top) > TOL_REST:
        msgs.append(f"({' '.join(goal)}): {x}'s bottom z = {bottom:.4f}, "
                    f"not on {y}'s support top z = {top:.4f}")
    return msgs


def _push_actions(sol: dict, solution: Path | None) -> set[str] | None:
    """The action schemas whose mode is `push` in the solution's modes file (None when
    there is none to read): a `move` action spans a motion with what it carries
    attached too, and is no push."""
    path = sol.get("modes")
    if not path or solution is None:
        return None
    try:
        modes = _resolve(path, solution)
    except FileNotFoundError:
        return None
    table = tomllib.loads(modes.read_text())
    return {name for name, spec in table.items()
            if isinstance(spec, dict) and spec.get("mode") == "push"}


def _goal_roles(sol: dict, solution: Path) -> dict[str, tuple[int, int]] | None:
    """goal_roles of the solution's domain and modes files (None when either is not
    found: the goal is read as (pred x y))."""
    try:
        return goal_roles(_resolve(sol["domain"], solution), _resolve(sol["modes"], solution))
    except (KeyError, TypeError, FileNotFoundError):
        return None


def check_replay(rp: Replay, sol: dict, goal, pushes: set[str] | None = None,
                 roles: dict[str, tuple[int, int]] | None = None) -> list[Violation]:
    names = sol["robot"]["joints"]
    traj = np.array(sol["trajectory"], dtype=float)
    phases = sol["phases"]
    poses = {n: [matrix(p[:3], p[3:]) for p in v] for n, v in sol["objects"].items()}
    movable = list(poses)
    own_fingers = any(f in names for f in FINGERS)
    out = _limits(rp, names, traj)
    worst: dict[tuple, tuple[float, Violation]] = {}
    held, rel, grasped = None, np.eye(4), False
    for k, ph in enumerate(phases):
        where = f"phase {k} ({ph['action'] or 'motion'})"
        att, s, e = ph["attached"], ph["start"], ph["end"]
        for n in movable:
            rp.place(n, poses[n][k])
        pushing = att is not None and ph["action"] is not None and e > s and (
            pushes is None or ph["action"].strip("()").split()[0] in pushes)
        if att and att != held:
            rp.set_q(names, traj[s], not own_fingers)
            rel = np.linalg.inv(rp.hand()) @ poses[att][k]
            grasped = not pushing and rp.model != "planar"
            if grasped:
                # The fingers close from their opening just before the grasp.
                first = next((names.index(f) for f in FINGERS if f in names), None)
                start = 0.04 if first is None else float(traj[max(s - 1, 0)][first])
                for a, b, d in rp.closing_sweep(att, start):
                    out.append(Violation("collision", where, f"{a} closes through {b} "
                                         f"({-d * 1000:.1f} mm deep) at waypoint {s}"))
                rp.set_q(names, traj[s], not own_fingers)
        held = att
        for t, q in _samples(traj, s, e):
            rp.set_q(names, q, not own_fingers)
            if att:
                m = rp.hand() @ rel
                rp.place(att, m)
                if grasped and not own_fingers:
                    rp.close_fingers(att)
                if pushing:
                    dz, tilt = pose_error(_upright(m), _upright(poses[att][k]))
                    if dz > TOL_POS or tilt > TOL_ANG:
                        out.append(Violation("attachment", where, f"pushed {att} lifts or tips "
                                             f"at waypoint {t:.1f} ({dz * 1000:.1f} mm, "
                                             f"{math.degrees(tilt):.1f} deg)"))
                        pushing = False
            for a, b, d in rp.penetrations(att, grasped, movable, t in (s, e)):
                key = (k, a, b)
                if key not in worst or d < worst[key][0]:
                    worst[key] = (d, Violation("collision", where, f"{a} and {b} penetrate by "
                                               f"{-d * 1000:.1f} mm at waypoint {t:.1f}"))
        for n in movable:
            if n == att:
                rp.set_q(names, traj[e], False)
                dp, da = pose_error(rp.hand() @ rel, poses[n][k + 1])
                what = f"{n} is not where the hand holds it at waypoint {e}"
            else:
                dp, da = pose_error(poses[n][k], poses[n][k + 1])
                what = f"{n} moves while not held"
            if dp > TOL_POS or da > TOL_ANG:
                out.append(Violation("attachment", where, f"{what}: off by {dp * 1000:.1f} mm, "
                                     f"{math.degrees(da):.1f} deg"))
        nxt = phases[k + 1]["attached"] if k + 1 < len(phases) else None
        for n in movable:
            rp.place(n, poses[n][k + 1])
        for n in movable:
            if n not in (att, nxt) and not rp.rests(n):
                out.append(Violation("support", where, f"{n} rests on nothing after this phase"))
    out += [v for _, v in sorted(worst.values(), key=lambda dv: dv[0])]
    for n in movable:
        rp.place(n, poses[n][-1])
    out += [Violation("goal", "end", m) for m in goal_failures(rp, goal, movable, roles)]
    return out


def _upright(m: np.ndarray) -> np.ndarray:
    """Height and tilt of a pose, without its x, y and yaw."""
    z = m[:3, 2]
    axis = np.cross([0.0, 0.0, 1.0], z)
    s, c = np.linalg.norm(axis), z[2]
    r = np.eye(3)
    if s > 1e-12:
        k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]]) / s
        r = np.eye(3) + s * k + (1 - c) * k @ k
    u = np.eye(4)
    u[:3, :3] = r
    u[2, 3] = m[2, 3]
    return u


def check_solution(solution: Path, scene: Path | None = None,
                   problem: Path | None = None) -> list[Violation]:
    """Every violation of the rules above; an empty list is a valid solution."""
    sol = json.loads(Path(solution).read_text())
    scene = Path(scene) if scene else _resolve(sol["scene"], Path(solution))
    problem = Path(problem) if problem else _resolve(sol["problem"], Path(solution))
    replay = Replay(scene)
    try:
        return check_replay(replay, sol, read_goal(problem), _push_actions(sol, Path(solution)),
                            _goal_roles(sol, Path(solution)))
    finally:
        replay.close()


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="checker", description=__doc__.splitlines()[0])
    ap.add_argument("solution", type=Path)
    ap.add_argument("--scene", type=Path)
    ap.add_argument("--problem", type=Path)
    a = ap.parse_args(argv)
    try:
        found = check_solution(a.solution, a.scene, a.problem)
    except (OSError, KeyError, ValueError, tomllib.TOMLDecodeError) as e:
        print(f"{a.solution}: cannot check: {type(e).__name__}: {e}", file=sys.stderr)
        return 2
    for v in found:
        print(v)
    print("valid" if not found else f"{len(found)} violation(s)")
    return 0 if not found else 1


if __name__ == "__main__":
    sys.exit(main())
