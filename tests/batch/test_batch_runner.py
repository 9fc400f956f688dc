"""The runner against real child processes: solved, bad input, crash, hang, memory."""

import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from tampcli.batch.child import CRASH_ENV, HANG_ENV, HANG_MARKER
from tampcli.batch.discover import Job, discover
from tampcli.batch.runner import RunOptions, child_command, run_job
from tampcli.errors import UsageError

from .common import GRIPPER_DOMAIN, GRIPPER_P01, HARD, alive_with, all_gone, problem_set

SYMBOLIC = RunOptions(symbolic=True, time_limit=60, grace=5)


def _job(problem: Path) -> Job:
    [job] = discover([str(problem)])
    return job


def test_solved_problem_has_cost_length_rss_and_stats():
    result = run_job(_job(GRIPPER_P01), SYMBOLIC)
    assert result.status == "solved", result.error
    assert result.cost == 11 and result.plan_length == 11
    assert result.exit_code == 0 and result.error is None
    assert 5 < result.peak_rss_mb < 2000
    assert 0 < result.cpu_s < result.wall_s + 1
    assert result.stats


def test_malformed_problem_is_an_error_with_its_location(tmp_path):
    [bad] = problem_set(tmp_path, ["bad.pddl"])
    result = run_job(_job(bad), SYMBOLIC)
    assert result.status == "error"
    assert result.exit_code == 2
    assert f"{bad}:4:2:" in result.error


def test_missing_domain_is_an_error_without_a_child(tmp_path):
    lonely = tmp_path / "lonely.pddl"
    lonely.write_text(GRIPPER_P01.read_text())
    result = run_job(_job(lonely), SYMBOLIC)
    assert result.status == "error" and "no domain file found" in result.error
    assert result.exit_code is None


def test_crash_hook_aborts_the_child_for_real(tmp_path, monkeypatch):
    a, b = problem_set(tmp_path, ["a.pddl", "boom.pddl"])
    monkeypatch.setenv(CRASH_ENV, "boom*")
    crashed = run_job(_job(b), SYMBOLIC)
    assert crashed.status == "crashed"
    assert "SIGABRT" in crashed.error
    assert crashed.exit_code is None
    assert run_job(_job(a), SYMBOLIC).status == "solved"


def test_hung_child_and_its_grandchild_are_killed_at_the_limit(tmp_path, monkeypatch):
    [slow] = problem_set(tmp_path, ["slow.pddl"])
    monkeypatch.setenv(HANG_ENV, str(slow))
    marker = f"{HANG_MARKER} {slow}"
    with ThreadPoolExecutor(1) as pool:
        start = time.monotonic()
        future = pool.submit(run_job, _job(slow), RunOptions(symbolic=True, time_limit=1,
                                                              grace=0.5))
        grandchildren = []
        while not grandchildren and not future.done():
            grandchildren = alive_with(marker)
            time.sleep(0.02)
        result = future.result()
        elapsed = time.monotonic() - start
    assert grandchildren, "the hung child never started its grandchild"
    assert result.status == "timeout"
    assert "time limit (1 s)" in result.error
    assert 1.5 <= result.wall_s and elapsed < 10
    # The grandchild was in the child's process group, so it died with it.
    assert all_gone(marker)


def test_hard_problem_past_its_limit_is_a_timeout():
    # grace 0: the batch's clock starts before the child's, so the batch kills it first.
    result = run_job(_job(HARD), RunOptions(symbolic=True, time_limit=1, grace=0))
    assert result.status == "timeout"
    assert 1.0 <= result.wall_s < 10


def test_memory_limit_blow_up_is_a_crash_that_says_memory():
    result = run_job(_job(GRIPPER_P01), RunOptions(symbolic=True, time_limit=60, memory_mb=20))
    assert result.status == "crashed"
    assert "out of memory (memory limit 20 MB)" in result.error


def test_generous_memory_limit_changes_nothing():
    result = run_job(_job(GRIPPER_P01), RunOptions(symbolic=True, time_limit=60, memory_mb=4000))
    assert result.status == "solved", result.error


def test_child_command_carries_limits_and_video(tmp_path):
    job = Job(str(GRIPPER_P01), str(GRIPPER_DOMAIN), "gripper")
    command = child_command(job, RunOptions(time_limit=7.5, memory_mb=512,
                                            video_dir=str(tmp_path)))
    args = command[command.index("--") + 1:]
    assert args[:4] == ["solve", str(GRIPPER_DOMAIN), str(GRIPPER_P01), "--json"]
    assert args[args.index("--time-limit") + 1] == "7.5"
    assert args[args.index("--video") + 1] == str(tmp_path / "gripper-prob01.mp4")
    assert command[command.index("--memory-mb") + 1] == "512"
    assert args[args.index("--jobs") + 1] == "1"  # problems side by side, not their skeletons
    symbolic = child_command(job, RunOptions(symbolic=True))
    assert symbolic[symbolic.index("--") + 1] == "plan" and "--time-limit" not in symbolic


@pytest.mark.parametrize("kwargs", [{"time_limit": 0}, {"time_limit": -1}, {"grace": -1},
                                    {"memory_mb": 0},
                                    {"symbolic": True, "video_dir": "v"}])
def test_bad_options_are_refused_when_built(kwargs):
    with pytest.raises(UsageError):
        RunOptions(**kwargs)
