"""Reading solution.json back: the one reader `render` and `validate` share.

The format lets other planners write what `solve` does not: several motion
phases between two actions (approach, descend, lift), none at all, motions
after the last action (a retreat), and a Panda's finger joints as extra
trajectory columns. `read_solution` accepts all of these, refuses what breaks
the structure (each error names the key, what was expected, what was found),
and gives the code downstream one canonical form besides the file as written.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

from tampcli.errors import SolutionFileError
from tampcli.geometry.arms import ARMS
from tampcli.solution import STATUSES, VERSION, Phase, SkeletonRecord, Solution
from tampcli.solution_kkt import stages_from_dict

# The finger joints a solution file may give as columns, per built-in robot model
# (geometry.arms: no simulator needed to read a file). A URDF arm's fingers are the
# scene's to name, which a file alone does not know: its solutions give none.
FINGERS_OF = {model: arm.fingers.joints for model, arm in ARMS.items() if arm.fingers}
FINGERED_MODELS = tuple(FINGERS_OF)

_ROBOT_NAMES = {"panda": "Panda", "kuka_iiwa": "KUKA iiwa", "xarm6": "xArm6"}

_REQUIRED = ("version", "domain", "problem", "scene", "status", "reason", "plan",
             "symbolic_cost", "cost", "lower_bound", "robot", "trajectory", "phases",
             "objects", "skeletons", "stats")


@dataclass(frozen=True)
class SolutionFile:
    """A checked solution: `raw` as written, `canonical` as downstream code wants it.

    `canonical` has the arm's columns only and one motion phase for each run of
    consecutive motion phases (their waypoint spans joined: phases share their
    boundary waypoint, so the trajectory and its indices are unchanged);
    `boundaries[k]` is the index into `raw`'s pose lists of canonical boundary
    k. `fingers` holds, at each waypoint, the value of each finger joint of the
    model (FINGERS_OF's order) when the file gives finger columns, else None
    (open, closed on a grasped object); joints that mimic them are the World's
    to add (solution_fit.finger_rows).
    """

    path: str
    raw: Solution
    canonical: Solution
    boundaries: tuple[int, ...]
    fingers: tuple[tuple[float, ...], ...] | None = None

    @property
    def retreat(self) -> Phase | None:
        """The motion after the last action, if the file has one."""
        phases = self.canonical.phases
        if len(phases) > 1 and phases[-1].action is None and any(
                p.action is not None for p in phases):
            return phases[-1]
        return None


def read_solution(path: str | Path) -> SolutionFile:
    """Read, check and canonicalize a solution.json; bad input raises SolutionFileError."""
    path = str(path)
    data = _load_json(path)
    for key in _REQUIRED:
        if key not in data:
            raise SolutionFileError("missing key: every solution.json has it", path, key=key)
    if data["version"] != VERSION:
        raise SolutionFileError(f"unsupported version {data['version']!r} (expected {VERSION})",
                                path, key="version")
    if not isinstance(data["robot"], dict):
        raise SolutionFileError(f"expected an object, found {data['robot']!r}", path,
                                key="robot")
    trajectory = _matrix(data["trajectory"], path, "trajectory")
    phases = tuple(_phase(p, i, path) for i, p in enumerate(_list(data["phases"], path,
                                                                   "phases")))
    objects = data["objects"]
    if not isinstance(objects, dict):
        raise SolutionFileError("expected an object of name -> poses", path, key="objects")
    objects = {name: [list(p) for p in _matrix(poses, path, f"objects.{name}")]
               for name, poses in objects.items()}
    plan = data["plan"]
    _strings(plan, path, "plan")
    raw = Solution(
        domain=data["domain"], problem=data["problem"], scene=data["scene"],
        status=data["status"], reason=data["reason"], plan=tuple(plan),
        symbolic_cost=data["symbolic_cost"], cost=data["cost"],
        lower_bound=data["lower_bound"], robot=data["robot"],
        trajectory=tuple(tuple(q) for q in trajectory), phases=phases, objects=objects,
        skeletons=_skeletons(data["skeletons"], path), stats=data["stats"],
        modes=data.get("modes"), objective=data.get("objective"),
        symbolic_weight=data.get("symbolic_weight"),
        kkt=stages_from_dict(data.get("kkt"), path, "kkt"),
        grasps=_grasps(data.get("grasps"), path))
    return check_solution(raw, path)


def _grasps(value, path: str) -> tuple[dict, ...]:
    """The optional `grasps` list (what solve reports of each grasp; nothing checks
    or uses it downstream): a list of objects, or absent."""
    if value is None:
        return ()
    if not isinstance(value, list) or not all(isinstance(g, dict) for g in value):
        raise SolutionFileError(f"expected a list of objects, found {value!r}"[:200], path,
                                key="grasps")
    return tuple(value)


def check_solution(sol: Solution, path: str = "<solution>") -> SolutionFile:
    """The structural checks on a Solution value (read from a file or built in
    memory), and its canonical form."""
    if sol.status not in STATUSES:
        raise SolutionFileError(f"expected one of {', '.join(STATUSES)}, found {sol.status!r}",
                                path, key="status")
    for key in ("domain", "problem", "scene", "modes"):
        value = getattr(sol, key)
        if value is not None and not isinstance(value, str):
            raise SolutionFileError(f"expected a path (a string), found {value!r}", path, key=key)
    _strings(sol.plan, path, "plan")
    model = sol.robot.get("model")
    if model is not None and not isinstance(model, str):
        raise SolutionFileError(f"expected a string, found {model!r}", path, key="robot.model")
    joints = sol.robot.get("joints", [])
    _strings(joints, path, "robot.joints")
    _check_trajectory(sol, joints, path)
    _check_phases(sol, path)
    _check_objects(sol, path)
    return _canonical(sol, path, tuple(joints))


def _load_json(path: str) -> dict:
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise SolutionFileError("file not found", path) from None
    except UnicodeDecodeError as err:
        raise SolutionFileError(f"not UTF-8 text (byte {err.start})", path) from None
    except OSError as err:
        raise SolutionFileError(f"cannot read: {err.strerror}", path) from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as err:
        lines = text.split("\n")
        raise SolutionFileError(f"not valid JSON: {err.msg}", path, err.lineno, err.colno,
                                lines[err.lineno - 1] if err.lineno <= len(lines) else None
                                ) from None
    except RecursionError:
        raise SolutionFileError("JSON nested too deeply", path) from None
    except ValueError as err:  # e.g. an integer with more digits than Python converts
        raise SolutionFileError(f"not valid JSON: {err}", path) from None
    if not isinstance(data, dict):
        raise SolutionFileError("expected a JSON object (a solution.json)", path, 1, 1)
    return data


def _skeletons(value, path: str) -> tuple[SkeletonRecord, ...]:
    records = []
    for i, s in enumerate(_list(value, path, "skeletons")):
        key = f"skeletons[{i}]"
        if not isinstance(s, dict):
            raise SolutionFileError(f"expected an object, found {s!r}", path, key=key)
        if "rank" in s and not _is_int(s["rank"]):
            raise SolutionFileError(f"expected an integer, found {s['rank']!r}", path,
                                    key=f"{key}.rank")
        plan = s.get("plan", [])
        _strings(plan, path, f"{key}.plan")
        seconds = s.get("seconds")
        if seconds is not None and not _is_number(seconds):
            raise SolutionFileError(f"expected a number, found {seconds!r}", path,
                                    key=f"{key}.seconds")
        records.append(SkeletonRecord(
            rank=s.get("rank", i + 1), plan=tuple(plan), symbolic_cost=s.get("symbolic_cost"),
            outcome=s.get("outcome", "not reached"), bound=s.get("bound"),
            bound_kind=s.get("bound_kind"), stage=s.get("stage"), nlp_cost=s.get("nlp_cost"),
            total_cost=s.get("total_cost"), seconds=float(seconds or 0.0),
            reason=s.get("reason"), kkt=stages_from_dict(s.get("kkt"), path, f"{key}.kkt")))
    return tuple(records)


def _check_trajectory(sol: Solution, joints, path: str) -> None:
    n = len(sol.trajectory)
    for i, q in enumerate(sol.trajectory):
        if len(q) != len(sol.trajectory[0]):
            raise SolutionFileError(f"waypoint {i} has {len(q)} joint values, waypoint 0 has "
                                    f"{len(sol.trajectory[0])}", path, key="trajectory")
        if not all(_finite(v) for v in q):
            raise SolutionFileError(f"waypoint {i} holds a non-finite value", path,
                                    key="trajectory")
    if n and len(joints) != len(sol.trajectory[0]):
        raise SolutionFileError(f"{len(joints)} joint names for waypoints of "
                                f"{len(sol.trajectory[0])} values", path, key="robot.joints")
    seen = set()
    for name in joints:
        if name in seen:
            raise SolutionFileError(f"joint {name!r} named twice", path, key="robot.joints")
        seen.add(name)
    model = sol.robot.get("model")
    own = FINGERS_OF.get(model, ())
    for name in joints:
        other = next((m for m, names in FINGERS_OF.items() if name in names and m != model),
                     None)
        if other is not None and name not in own:
            raise SolutionFileError(f"{name!r} is a finger joint of the {_ROBOT_NAMES[other]}, "
                                    f"but the robot is {model!r}", path, key="robot.joints")
    fingers = [name for name in joints if name in own]
    if fingers and len(fingers) == len(joints):
        raise SolutionFileError("only finger joints: the arm's joints are missing", path,
                                key="robot.joints")


def _check_phases(sol: Solution, path: str) -> None:
    """Phases tile the trajectory (each starts where the previous one ended), the
    action phases are the plan's steps in order, and the motions between two
    actions all carry the same object."""
    n = len(sol.trajectory)
    if not sol.phases:
        if n > 1:
            raise SolutionFileError(f"no phases for a trajectory of {n} waypoints: phases "
                                    "must cover it", path, key="phases")
        return
    expected, actions, held = 0, [], None
    for i, phase in enumerate(sol.phases):
        key = f"phases[{i}]"
        for field in ("action", "attached"):
            value = getattr(phase, field)
            if value is not None and not isinstance(value, str):
                raise SolutionFileError(f"expected a string or null, found {value!r}", path,
                                        key=f"{key}.{field}")
        if not (_is_int(phase.start) and _is_int(phase.end)
                and 0 <= phase.start <= phase.end < n):
            raise SolutionFileError(f"start/end out of range: expected 0 <= start <= end < "
                                    f"{n} (the trajectory has {n} waypoints), found "
                                    f"{phase.start!r}, {phase.end!r}", path, key=key)
        if phase.start != expected:
            where = "the first phase starts at waypoint 0" if i == 0 else \
                f"a phase starts where the previous one ended (phases[{i - 1}].end)"
            raise SolutionFileError(f"starts at {phase.start}, expected {expected}: {where}",
                                    path, key=f"{key}.start")
        expected = phase.end
        if phase.action is not None:
            actions.append((i, phase.action))
            held = None
        elif held is not None and held[1] != phase.attached:
            raise SolutionFileError(
                f"expected {held[1]!r} as in phases[{held[0]}]: consecutive motion phases "
                f"carry the same object (only an action changes it), found {phase.attached!r}",
                path, key=f"{key}.attached")
        else:
            held = held or (i, phase.attached)
    if expected != n - 1:
        raise SolutionFileError(f"ends at {expected}, expected {n - 1}: the last phase ends "
                                "at the last waypoint", path,
                                key=f"phases[{len(sol.phases) - 1}].end")
    _check_actions(sol, actions, path)


def _check_actions(sol: Solution, actions, path: str) -> None:
    for k, (i, action) in enumerate(actions):
        if k >= len(sol.plan):
            raise SolutionFileError(f"expected {len(sol.plan)} action phases (one per plan "
                                    f"step), found an action phase more: {action!r}", path,
                                    key=f"phases[{i}].action")
        if _step_words(action) != _step_words(sol.plan[k]):
            raise SolutionFileError(f"expected {sol.plan[k]!r} (plan[{k}]): action phases "
                                    f"follow the plan in order, found {action!r}", path,
                                    key=f"phases[{i}].action")
    if len(actions) < len(sol.plan):
        raise SolutionFileError(f"expected an action phase for each of the {len(sol.plan)} plan "
                                f"steps, found {len(actions)}: none for "
                                f"{sol.plan[len(actions)]!r}", path, key="phases")


def _step_words(action: str) -> tuple[str, ...]:
    return tuple(action.replace("(", " ").replace(")", " ").lower().split())


def _check_objects(sol: Solution, path: str) -> None:
    if not isinstance(sol.objects, dict):
        raise SolutionFileError("expected an object of name -> poses", path, key="objects")
    for name, poses in sol.objects.items():
        key = f"objects.{name}"
        _list(poses, path, key)
        if len(poses) != len(sol.phases) + 1:
            raise SolutionFileError(f"expected {len(sol.phases) + 1} poses (one before the "
                                    f"first phase, one after each), found {len(poses)}",
                                    path, key=key)
        for k, pose in enumerate(poses):
            if len(pose) != 7 or not all(_finite(v) for v in pose):
                raise SolutionFileError(f"pose {k}: expected 7 finite numbers "
                                        f"[x y z qx qy qz qw], found {list(pose)!r}", path,
                                        key=key)
            if math.hypot(*pose[3:]) < 1e-9:
                raise SolutionFileError(f"pose {k} has a zero quaternion (no rotation is "
                                        "[0, 0, 0, 1])", path, key=key)


def _canonical(sol: Solution, path: str, joints: tuple[str, ...]) -> SolutionFile:
    own = FINGERS_OF.get(sol.robot.get("model"), ())
    arm = [j for j, name in enumerate(joints) if name not in own]
    finger_columns = [joints.index(name) if name in joints else None for name in own]
    phases: list[Phase] = []
    boundaries = [0]
    for i, phase in enumerate(sol.phases):
        if phase.action is None and phases and phases[-1].action is None:
            phases[-1] = Phase(None, phases[-1].start, phase.end, phase.attached)
            boundaries[-1] = i + 1
        else:
            phases.append(phase)
            boundaries.append(i + 1)
    fingers = None
    given = [c for c in finger_columns if c is not None]
    if given:
        # A finger column left out takes the first given one's value: the Panda's
        # two fingers move together (the second mimics the first on the real hand).
        columns = [given[0] if c is None else c for c in finger_columns]
        fingers = tuple(tuple(float(q[c]) for c in columns) for q in sol.trajectory)
    if len(arm) == len(joints):
        trajectory, robot = sol.trajectory, sol.robot
    else:
        trajectory = tuple(tuple(q[j] for j in arm) for q in sol.trajectory)
        robot = {**sol.robot, "joints": [joints[j] for j in arm]}
    objects = {name: [poses[b] for b in boundaries] for name, poses in sol.objects.items()}
    canonical = Solution(**{**sol.__dict__, "trajectory": trajectory, "robot": robot,
                            "phases": tuple(phases), "objects": objects})
    return SolutionFile(path, sol, canonical, tuple(boundaries), fingers)


def _phase(p, i: int, path: str) -> Phase:
    key = f"phases[{i}]"
    if not isinstance(p, dict) or not {"action", "start", "end", "attached"} <= set(p):
        raise SolutionFileError(f"needs action, start, end and attached; found {p!r}",
                                path, key=key)
    return Phase(p["action"], p["start"], p["end"], p["attached"])


def _list(value, path: str, key: str) -> list:
    if not isinstance(value, (list, tuple)):
        raise SolutionFileError(f"expected a list, found {value!r}", path, key=key)
    return value


def _matrix(value, path: str, key: str) -> list:
    rows = _list(value, path, key)
    for i, row in enumerate(rows):
        if not isinstance(row, (list, tuple)) or not all(_is_number(v) for v in row):
            raise SolutionFileError(f"entry {i} is not a list of numbers: {row!r}", path,
                                    key=key)
    return rows


def _strings(value, path: str, key: str) -> None:
    if not isinstance(value, (list, tuple)):
        raise SolutionFileError(f"expected a list of strings, found {value!r}", path, key=key)
    for i, item in enumerate(value):
        if not isinstance(item, str):
            raise SolutionFileError(f"expected a string \"(action arg ...)\" or a name, found "
                                    f"{item!r}", path, key=f"{key}[{i}]")


def _is_int(value) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _finite(value) -> bool:
    """JSON integers have no size limit: one too large for a float is not finite."""
    try:
        return math.isfinite(value)
    except OverflowError:
        return False
