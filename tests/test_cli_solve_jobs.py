"""`tampcli solve --jobs N`: skeletons solved in worker processes give the serial
answer; a bad N is a usage error; a worker that dies is reported, not a traceback."""

import json
import multiprocessing
import threading
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOMAINS, PROBLEMS = ROOT / "domains", ROOT / "problems"


def _solve(cli, tmp_path, domain, problem, *flags):
    out = tmp_path / f"{domain}-{problem}-{'-'.join(flags)}.json"
    run = cli("solve", "--out", out, *flags, DOMAINS / domain / "domain.pddl",
              PROBLEMS / domain / f"{problem}.pddl")
    return run, out


@pytest.mark.parametrize("domain", ["planar-tamp", "arm-pick-place"])
def test_two_jobs_give_the_serial_answer(cli, tmp_path, domain):
    serial, serial_out = _solve(cli, tmp_path, domain, "p01", "--jobs", "1")
    parallel, parallel_out = _solve(cli, tmp_path, domain, "p01", "--jobs", "2")
    assert serial.code == parallel.code == 0, parallel.err
    one, two = (json.loads(p.read_text()) for p in (serial_out, parallel_out))
    assert two["plan"] == one["plan"]
    assert two["objective"] == pytest.approx(one["objective"], abs=1e-6)
    assert "Traceback" not in parallel.err
    check = cli("validate", DOMAINS / domain / "domain.pddl",
                PROBLEMS / domain / "p01.pddl", parallel_out)
    assert check.code == 0, check.out + check.err


def test_two_jobs_draw_no_regrasp_the_serial_search_would_not(cli, tmp_path):
    """arm-pick-place p03 has two loopless skeletons, both feasible: the serial search
    stops there; two jobs used to draw 18 regrasps while those two were out (the
    source decides on regrasps by their results: LearningSource.waiting_on_results)."""
    runs = [_solve(cli, tmp_path, "arm-pick-place", "p03", "--jobs", jobs)
            for jobs in ("1", "2")]
    assert all(run.code == 0 for run, _ in runs), runs[1][0].err
    one, two = (json.loads(out.read_text()) for _, out in runs)
    assert two["stats"]["skeletons_generated"] == one["stats"]["skeletons_generated"] == 2
    assert two["objective"] == pytest.approx(one["objective"], abs=1e-6)


@pytest.mark.parametrize("bad", ["-1", "-3"])
def test_a_bad_job_count_is_a_usage_error(cli, tmp_path, bad):
    run, out = _solve(cli, tmp_path, "planar-tamp", "p01", "--jobs", bad)
    assert run.code == 2
    assert f"--jobs: must be an integer >= 0, got {bad}" in run.err
    assert not out.exists()


def test_a_worker_killed_mid_solve_is_reported_and_the_search_goes_on(cli, tmp_path):
    """arm-sort's skeletons take seconds each. Its first answer (#1) is found in this
    process, alone; then #2 is solved here and #3 by the worker. Workers are killed
    every 0.3 s (a fresh one takes about a second to set up): #3 fails with the
    reason, and the search goes on."""
    stop = threading.Event()

    def kill_workers():
        while not stop.wait(0.3):
            for child in multiprocessing.active_children():
                child.kill()

    killer = threading.Thread(target=kill_workers, daemon=True)
    killer.start()
    try:
        run, out = _solve(cli, tmp_path, "arm-sort", "p01", "--jobs", "2", "-k", "3",
                          "--time-limit", "60")
    finally:
        stop.set()
        killer.join()
    assert run.code in (0, 1), run.err
    assert "Traceback" not in run.err + run.out
    sol = json.loads(out.read_text())
    killed = [s for s in sol["skeletons"] if "worker failed" in (s["reason"] or "")]
    assert killed and all(s["outcome"] == "infeasible" for s in killed)
    assert all("BrokenProcessPool" in s["reason"] for s in killed)
    assert "worker failed" in run.err  # the skeleton table says why
    assert len(sol["skeletons"]) == 3


def test_the_workers_end_when_the_solve_is_killed(tmp_path):
    """A solve killed outright (SIGKILL: no chance to end its pool) leaves no worker
    behind: each ends once its parent is gone (skeleton_pool._end_with)."""
    import os
    import signal
    import subprocess
    import sys
    import time

    solve = subprocess.Popen(
        [sys.executable, "-m", "tampcli", "solve", "--quiet", "--jobs", "2",
         str(DOMAINS / "arm-sort" / "domain.pddl"), str(PROBLEMS / "arm-sort" / "p01.pddl")],
        cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    def children() -> list[int]:
        out = subprocess.run(["ps", "-o", "pid=", "--ppid", str(solve.pid)],
                             capture_output=True, text=True).stdout
        return [int(p) for p in out.split()]

    try:
        until = time.monotonic() + 30
        while not children() and time.monotonic() < until:
            time.sleep(0.1)
        workers = children()
        assert workers, "no worker started"
        time.sleep(1.0)  # set up (or setting up)
    finally:
        solve.send_signal(signal.SIGKILL)
        solve.wait()

    def alive(pid: int) -> bool:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return False
        with open(f"/proc/{pid}/stat") as f:  # a zombie is gone but for its entry
            return f.read().split(")")[-1].split()[0] != "Z"

    until = time.monotonic() + 10
    while any(alive(p) for p in workers) and time.monotonic() < until:
        time.sleep(0.2)
    assert not any(alive(p) for p in workers)
