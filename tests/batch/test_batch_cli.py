"""`tampcli batch` end to end, with real children: failures, SIGKILL + resume, Dask."""

import contextlib
import csv
import io
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from rich.console import Console

from tampcli.batch.child import CRASH_ENV, HANG_ENV, HANG_MARKER
from tampcli.cli import main
from tampcli.cli.ui import UI

from .common import GRIPPER_P01, IPC, ROOT, alive_with, all_gone, problem_set


def _lines(path: Path) -> list[dict]:
    text = path.read_text()
    assert text == "" or text.endswith("\n")
    return [json.loads(line) for line in text.splitlines()]


def _statuses(path: Path) -> dict[str, str]:
    return {Path(r["problem"]).name: r["status"] for r in _lines(path)}


@pytest.fixture
def failing_set(tmp_path, monkeypatch):
    """good.pddl solves; bad.pddl is malformed; boom.pddl crashes its child;
    slow.pddl hangs past any limit."""
    folder = tmp_path / "set"
    problem_set(folder, ["good.pddl", "bad.pddl", "boom.pddl", "slow.pddl"])
    monkeypatch.setenv(CRASH_ENV, "boom.pddl")
    monkeypatch.setenv(HANG_ENV, "slow.pddl")
    return folder


# slow.pddl is killed at 7 s; the others finish long before, even on a loaded machine.
LIMITS = ("--time-limit", "6", "--grace", "1")
EXPECTED = {"good.pddl": "solved", "bad.pddl": "error", "boom.pddl": "crashed",
            "slow.pddl": "timeout"}


def test_each_failure_is_a_line_with_its_status_and_the_batch_goes_on(cli, failing_set,
                                                                        tmp_path):
    out = tmp_path / "r.jsonl"
    run = cli("batch", failing_set, "--symbolic", *LIMITS,
              "-j", "2", "--out", out, "--json", "--csv", tmp_path / "r.csv")
    assert run.code == 0, run.err
    assert _statuses(out) == EXPECTED
    by_name = {Path(r["problem"]).name: r for r in _lines(out)}
    assert by_name["good.pddl"]["cost"] == 11 and by_name["good.pddl"]["plan_length"] == 11
    assert "bad.pddl:4:2:" in by_name["bad.pddl"]["error"]
    assert "SIGABRT" in by_name["boom.pddl"]["error"]
    assert by_name["slow.pddl"]["wall_s"] >= 7
    summary = json.loads(run.out)
    assert summary["problems"] == 4 and summary["ran"] == 4
    assert summary["counts"] == {"solved": 1, "unsolvable": 0, "limit": 0, "timeout": 1,
                                 "error": 1, "crashed": 1}
    assert [d["domain"] for d in summary["domains"]] == ["set"]
    with open(tmp_path / "r.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert {Path(r["problem"]).name: r["status"] for r in rows} == EXPECTED
    # Piped output: one plain progress line per problem on stderr.
    assert run.err.count("] ") == 4 and "[4/4]" in run.err


def test_without_symbolic_the_batch_runs_solve(cli, tmp_path):
    # A problem without a scene: solve plans it symbolically and says so in its stats.
    out = tmp_path / "r.jsonl"
    run = cli("batch", ROOT / "problems" / "blocksworld" / "p01.pddl", "--out", out,
              "--time-limit", "60")
    assert run.code == 0, run.err
    [record] = _lines(out)
    assert record["status"] == "solved", record["error"]
    assert record["cost"] == 6 and record["plan_length"] == 6
    assert record["domain"].endswith("domains/blocksworld/domain.pddl")


def test_sigkill_mid_batch_then_resume_records_each_problem_once(cli, tmp_path):
    folder = tmp_path / "many"
    names = [f"p{i}.pddl" for i in range(1, 7)] + ["bad.pddl"]
    problem_set(folder, names)
    out = tmp_path / "r.jsonl"
    batch = subprocess.Popen([sys.executable, "-m", "tampcli", "batch", str(folder), "--symbolic",
                              "-j", "1", "--out", str(out), "-q"], cwd=ROOT,
                             start_new_session=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and not (out.exists() and out.read_text().count("\n")):
        time.sleep(0.05)
    os.kill(batch.pid, signal.SIGKILL)
    batch.wait()
    # The child running at that moment (now `python -m tampcli plan ...` on a problem
    # of the folder) dies with the batch (parent-death signal, kept across its exec).
    assert all_gone(str(folder))
    done_before = len(_lines(out))
    assert 1 <= done_before < len(names)
    run = cli("batch", folder, "--symbolic", "--resume", "--out", out, "--json")
    assert run.code == 0, run.err
    records = _lines(out)
    assert sorted(Path(r["problem"]).name for r in records) == sorted(names)
    assert _statuses(out) == {**dict.fromkeys(names, "solved"), "bad.pddl": "error"}
    summary = json.loads(run.out)
    assert summary["problems"] == len(names) and summary["skipped"] == done_before


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_ctrl_c_or_sigterm_kills_running_children_and_their_groups(tmp_path, signum):
    folder = tmp_path / "hang"
    [slow] = problem_set(folder, ["slow.pddl"])
    env = dict(os.environ, **{HANG_ENV: str(slow)})
    batch = subprocess.Popen([sys.executable, "-m", "tampcli", "batch", str(folder), "--symbolic",
                              "--out", str(tmp_path / "r.jsonl"), "-q"], cwd=ROOT, env=env,
                             stderr=subprocess.PIPE, text=True)
    marker = f"{HANG_MARKER} {slow}"
    deadline = time.monotonic() + 60
    while not alive_with(marker) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert alive_with(marker), "the hung child never started its grandchild"
    batch.send_signal(signum)
    _, err = batch.communicate(timeout=30)
    assert batch.returncode == 130 and "interrupted" in err
    assert all_gone(marker) and all_gone(str(slow))


def test_torn_last_line_is_cut_and_that_problem_runs_again(cli, tmp_path):
    folder = tmp_path / "s"
    problem_set(folder, ["a.pddl", "b.pddl"])
    out = tmp_path / "r.jsonl"
    assert cli("batch", folder / "a.pddl", "--symbolic", "--out", out).code == 0
    line = out.read_text()
    torn = line.replace("a.pddl", "b.pddl")[: len(line) // 2]
    with open(out, "a") as f:
        f.write(torn)
    run = cli("batch", folder, "--symbolic", "--resume", "--out", out)
    assert run.code == 0, run.err
    assert "torn last line" in run.err
    assert _statuses(out) == {"a.pddl": "solved", "b.pddl": "solved"}


def test_existing_results_without_resume_are_kept_and_refused(cli, tmp_path):
    out = tmp_path / "r.jsonl"
    out.write_text('{"problem": "x.pddl", "status": "solved"}\n')
    run = cli("batch", GRIPPER_P01, "--symbolic", "--out", out)
    assert run.code == 2 and "--resume" in run.err
    assert out.read_text() == '{"problem": "x.pddl", "status": "solved"}\n'


@pytest.mark.parametrize("argv, message", [
    (["nope/"], "no such file or folder"),
    ([str(IPC / "gripper" / "domain.pddl")], "no problem files found"),
    ([str(GRIPPER_P01), "--jobs", "0"], "must be at least 1"),
    ([str(GRIPPER_P01), "--time-limit", "-3"], "must be positive"),
    ([str(GRIPPER_P01), "--symbolic", "--video-dir", "v"], "videos need `solve`"),
    ([str(GRIPPER_P01), "--jobs", "many"], "invalid int value"),
    ([str(GRIPPER_P01), "--csv", "no/such/folder/r.csv"], "its folder does not exist"),
])
def test_bad_input_is_exit_2_without_traceback(cli, tmp_path, argv, message):
    run = cli("batch", *argv, "--out", tmp_path / "r.jsonl")
    assert run.code == 2
    assert message in run.err and "Traceback" not in run.err
    assert not (tmp_path / "r.jsonl").exists()


def test_terminal_shows_a_progress_bar_and_the_summary_table(tmp_path):
    out_text, err_text = io.StringIO(), io.StringIO()
    ui = UI(Console(file=out_text, force_terminal=True, width=120),
            Console(file=err_text, width=120))
    code = main(["batch", str(GRIPPER_P01), "--symbolic", "--out", str(tmp_path / "r.jsonl")], ui)
    assert code == 0
    shown = out_text.getvalue()
    assert "ETA" in shown and "1/1" in shown
    assert "gripper" in shown and "solved" in shown


@pytest.fixture(scope="module")
def cluster():
    """A Dask cluster whose worker is a process of its own, as on a real cluster:
    jobs are pickled to it and children are started from it. The test hooks
    are in the worker's environment from its start."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=True,
                                  dashboard_address=None,
                                  env={CRASH_ENV: "boom.pddl", HANG_ENV: "slow.pddl"}) as c:
        yield c


def test_dask_cluster_gives_the_same_statuses_as_local(cli, cluster, failing_set, tmp_path):
    out = tmp_path / "dask.jsonl"
    run = cli("batch", failing_set, "--symbolic", *LIMITS,
              "--out", out, "--scheduler", cluster.scheduler_address, "-q")
    assert run.code == 0, run.err
    assert _statuses(out) == EXPECTED
    by_name = {Path(r["problem"]).name: r for r in _lines(out)}
    assert by_name["good.pddl"]["cost"] == 11
    # Resume semantics hold on the cluster too: nothing left to run.
    again = cli("batch", failing_set, "--symbolic", "--resume", "--out", out, "--json",
                "--scheduler", cluster.scheduler_address)
    assert again.code == 0 and json.loads(again.out)["ran"] == 0
    assert len(_lines(out)) == 4


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGKILL], ids=["SIGTERM", "SIGKILL"])
def test_a_stopped_cluster_batch_kills_its_children_on_the_workers(cluster, tmp_path, signum):
    folder = tmp_path / "hang"
    [slow] = problem_set(folder, ["slow.pddl"])
    out = tmp_path / "r.jsonl"
    # A limit far away: what kills the child here is the batch being stopped.
    batch = subprocess.Popen([sys.executable, "-m", "tampcli", "batch", str(folder), "--symbolic",
                              "--time-limit", "600", "--out", str(out), "-q",
                              "--scheduler", cluster.scheduler_address], cwd=ROOT,
                             stderr=subprocess.PIPE, text=True)
    marker = f"{HANG_MARKER} {slow}"
    try:
        deadline = time.monotonic() + 60
        while not alive_with(marker) and time.monotonic() < deadline and batch.poll() is None:
            time.sleep(0.05)
        assert alive_with(marker), "the hung child never started its grandchild"
        batch.send_signal(signum)
        _, err = batch.communicate(timeout=30)
        if signum == signal.SIGTERM:
            assert batch.returncode == 130 and "interrupted" in err
        # The child's command line and its grandchild's both name the problem.
        assert all_gone(str(slow))
        # Stopped, not finished: nothing to record.
        assert out.read_text() == ""
    finally:
        # On failure, leave no hour-long sleeper behind (they ignore SIGTERM).
        if batch.poll() is None:
            batch.kill()
        for pid in alive_with(str(slow)):
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, signal.SIGKILL)


def test_bad_scheduler_address_is_a_usage_error(cli, tmp_path):
    pytest.importorskip("distributed")
    run = cli("batch", GRIPPER_P01, "--symbolic", "--scheduler", "nonsense://x",
              "--out", tmp_path / "r.jsonl")
    assert run.code == 2
    assert "tampcli batch: --scheduler: not a Dask scheduler address" in run.err


def test_missing_dask_is_a_clear_usage_error(tmp_path):
    code = (
        "import sys; sys.modules['distributed'] = None\n"
        "from tampcli.cli import main\n"
        f"sys.exit(main(['batch', {str(GRIPPER_P01)!r}, '--symbolic', '--scheduler', "
        f"'tcp://127.0.0.1:1', '--out', {str(tmp_path / 'r.jsonl')!r}]))\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert run.returncode == 2
    assert "tampcli[cluster]" in run.stderr and "Traceback" not in run.stderr


def test_results_name_problems_so_a_copied_set_resumes_from_its_own_file(cli, tmp_path):
    # --resume matches problems by path: a copy of a set is a different set.
    first = tmp_path / "one"
    problem_set(first, ["a.pddl"])
    out = tmp_path / "r.jsonl"
    assert cli("batch", first, "--symbolic", "--out", out).code == 0
    second = tmp_path / "two"
    shutil.copytree(first, second)
    run = cli("batch", second, "--symbolic", "--resume", "--out", out, "--json")
    assert json.loads(run.out)["ran"] == 1
    assert len(_lines(out)) == 2


def test_resume_from_another_working_directory_skips_what_is_done(cli, tmp_path, monkeypatch):
    x = tmp_path / "x"
    problem_set(x / "set", ["a.pddl", "b.pddl"])
    monkeypatch.chdir(x)
    assert cli("batch", "set/a.pddl", "--symbolic", "--out", "r.jsonl").code == 0
    [first] = _lines(x / "r.jsonl")
    assert first["problem"] == str(x / "set" / "a.pddl") and first["problem_rel"] == "set/a.pddl"
    monkeypatch.chdir(tmp_path)
    run = cli("batch", "x/set", "--symbolic", "--resume", "--out", "x/r.jsonl", "--json")
    assert run.code == 0, run.err
    summary = json.loads(run.out)
    assert summary["ran"] == 1 and summary["skipped"] == 1
    assert sorted(r["problem"] for r in _lines(x / "r.jsonl")) == [
        str(x / "set" / "a.pddl"), str(x / "set" / "b.pddl")]


def test_a_results_file_moved_with_its_set_still_resumes(cli, tmp_path, monkeypatch):
    # As when an experiment folder is copied to another machine.
    old = tmp_path / "machine-a" / "exp"
    problem_set(old / "set", ["a.pddl", "b.pddl"])
    monkeypatch.chdir(old)
    assert cli("batch", "set/a.pddl", "--symbolic", "--out", "r.jsonl").code == 0
    new = tmp_path / "machine-b" / "exp"
    shutil.copytree(old, new)
    shutil.rmtree(old)
    monkeypatch.chdir(tmp_path)
    run = cli("batch", new / "set", "--symbolic", "--resume", "--out", new / "r.jsonl", "--json")
    assert run.code == 0, run.err
    summary = json.loads(run.out)
    assert summary["ran"] == 1 and summary["problems"] == 2
    assert sorted(r["problem_rel"] for r in _lines(new / "r.jsonl")) == ["set/a.pddl",
                                                                         "set/b.pddl"]


def test_without_time_limit_a_hung_problem_is_killed_at_the_default(cli, tmp_path, monkeypatch):
    import tampcli.cli.batch as batch_cli

    # The default (300 s) made short enough to wait for.
    monkeypatch.setattr(batch_cli, "DEFAULT_TIME_LIMIT_S", 1.0)
    [slow] = problem_set(tmp_path / "s", ["slow.pddl"])
    monkeypatch.setenv(HANG_ENV, "slow.pddl")
    out = tmp_path / "r.jsonl"
    run = cli("batch", slow, "--symbolic", "--grace", "0.5", "--out", out, "-q")
    assert run.code == 0, run.err
    [record] = _lines(out)
    assert record["status"] == "timeout" and "time limit (1 s)" in record["error"]


@pytest.mark.parametrize("argv, limit", [([], 300.0), (["--time-limit", "7.5"], 7.5),
                                         (["--time-limit", "none"], None)])
def test_time_limit_defaults_to_300_s_and_none_lifts_it(cli, tmp_path, monkeypatch, argv,
                                                          limit):
    import tampcli.batch.local as local

    seen = []
    monkeypatch.setattr(local, "run_local", lambda jobs, options, *_: seen.append(options))
    run = cli("batch", GRIPPER_P01, "--symbolic", "--out", tmp_path / "r.jsonl", *argv)
    assert run.code == 0, run.err
    assert [options.time_limit for options in seen] == [limit]


def test_help_names_the_default_time_limit(capsys):
    with pytest.raises(SystemExit):
        main(["batch", "--help"])
    shown = " ".join(capsys.readouterr().out.split())
    assert "--time-limit S seconds per problem" in shown and "(default 300;" in shown
    assert "`none`: no limit" in shown
