"""Paths and small real inputs shared by the batch tests."""

import os
import shutil
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
IPC = ROOT / "benchmarks" / "ipc"
GRIPPER_DOMAIN = IPC / "gripper" / "domain.pddl"
GRIPPER_P01 = IPC / "gripper" / "prob01.pddl"
# Hard enough that `plan` cannot finish it within a second, even on a fast machine.
HARD = IPC / "depot" / "p15.pddl"

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


def alive_with(marker: str) -> list[int]:
    """Pids of live (not zombie) processes whose command line contains `marker`."""
    pids = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            cmdline = Path(f"/proc/{entry}/cmdline").read_bytes().replace(b"\0", b" ").decode()
            state = Path(f"/proc/{entry}/stat").read_text().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if marker in cmdline and state != "Z":
            pids.append(int(entry))
    return pids


def all_gone(marker: str, timeout: float = 10.0) -> bool:
    """Whether every process matching `marker` is dead within `timeout` s
    (a SIGKILLed process takes a moment to exit)."""
    deadline = time.monotonic() + timeout
    while alive_with(marker):
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True
