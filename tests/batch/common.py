"""Paths and small real inputs shared by the batch tests."""

import shutil
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
IPC = ROOT.parent / "shared" / "benchmarks" / "ipc"
GRIPPER_DOMAIN = IPC / "gripper" / "domain.pddl"
GRIPPER_P01 = IPC / "gripper" / "prob01.pddl"
# Hard enough that `plan` cannot finish it within a second, even on a fast machine.
HARD = IPC / "gripper" / "prob20.pddl"

MALFORMED = "(define (problem bad)\n (:domain gripper-strips)\n (:objects a b\n (:init (room a))\n"


def problem_set(folder: Path, names: list[str]) -> list[Path]:
    """Copies of gripper prob01 under `names` beside the gripper domain, plus
    `bad.pddl` (a syntax error on line 4) when asked for by name."""
    folder.mkdir(parents=True, exist_ok=True)
    shutil.copy(GRIPPER_DOMAIN, folder / "domain.pddl")
    paths = []
    for name in names:
        path = folder / name
        if name == "bad.pddl":
            path.write_text(MALFORMED)
        else:
            shutil.copy(GRIPPER_P01, path)
        paths.append(path)
    return paths
