import json
import os

import pytest

from tampcli.batch.results import Result, ResultsFile, read_results
from tampcli.errors import InputError, UsageError


def _result(name: str, **kw) -> Result:
    return Result(problem=name, domain="d.pddl", status=kw.pop("status", "solved"), **kw)


def test_append_writes_one_parseable_line_per_result(tmp_path):
    out = tmp_path / "sub" / "r.jsonl"
    with ResultsFile(str(out), resume=False) as results:
        results.append(_result("a.pddl", cost=3.0, plan_length=3, stats={"x": 1}))
        results.append(_result("b.pddl", status="crashed", error="killed by SIGABRT"))
    lines = out.read_text().splitlines()
    assert [json.loads(line)["problem"] for line in lines] == ["a.pddl", "b.pddl"]
    first = json.loads(lines[0])
    assert set(first) >= {"problem", "domain", "status", "cost", "plan_length", "wall_s",
                          "peak_rss_mb", "stats", "error"}
    assert first["error"] is None and first["stats"] == {"x": 1}


def test_non_finite_numbers_become_null_so_every_line_is_strict_json(tmp_path):
    out = tmp_path / "r.jsonl"
    with ResultsFile(str(out), resume=False) as results:
        results.append(_result("a.pddl", cost=float("inf"), stats={"h": [float("nan"), 1.0]}))
    record = json.loads(out.read_text(), parse_constant=lambda c: pytest.fail(c))
    assert record["cost"] is None and record["stats"]["h"] == [None, 1.0]


def test_unknown_status_is_refused():
    with pytest.raises(ValueError):
        _result("a.pddl", status="maybe")


def test_existing_results_need_resume(tmp_path):
    out = tmp_path / "r.jsonl"
    out.write_text(json.dumps({"problem": str(tmp_path / "a.pddl")}) + "\n")
    with pytest.raises(UsageError, match="--resume"):
        ResultsFile(str(out), resume=False)
    with ResultsFile(str(out), resume=True) as results:
        assert set(results.latest([str(tmp_path / "a.pddl")])) == {str(tmp_path / "a.pddl")}


def test_torn_last_line_is_cut_on_resume(tmp_path):
    out = tmp_path / "r.jsonl"
    good = json.dumps(_result("a.pddl").to_json()) + "\n"
    torn = json.dumps(_result("b.pddl").to_json())[:37]
    out.write_text(good + torn)
    with ResultsFile(str(out), resume=True) as results:
        assert results.repaired_bytes == len(torn)
        assert set(results.latest(map(os.path.abspath, ["a.pddl", "b.pddl"]))) == {
            os.path.abspath("a.pddl")}
        results.append(_result("b.pddl"))
    assert [json.loads(line)["problem"] for line in out.read_text().splitlines()] == [
        "a.pddl", "b.pddl"]


def test_torn_tail_longer_than_a_read_block(tmp_path):
    out = tmp_path / "r.jsonl"
    good = json.dumps(_result("a.pddl").to_json()) + "\n"
    out.write_text(good + "x" * 10000)
    with ResultsFile(str(out), resume=True) as results:
        assert results.repaired_bytes == 10000
    assert out.read_text() == good


def test_a_file_that_is_only_a_fragment_becomes_empty(tmp_path):
    out = tmp_path / "r.jsonl"
    out.write_text('{"problem": "a.p')
    with ResultsFile(str(out), resume=True) as results:
        assert results.records == []
    assert out.read_text() == ""


def test_a_bad_complete_line_is_bad_input_with_its_line_number(tmp_path):
    out = tmp_path / "r.jsonl"
    out.write_text('{"problem": "a.pddl"}\nhello\n{"problem": "b.pddl"}\n')
    with pytest.raises(InputError) as err:
        read_results(str(out))
    assert err.value.line == 2 and "not a results line" in err.value.render()
    out.write_text('{"problem": "a.pddl"}\n[1, 2]\n')
    with pytest.raises(InputError, match="not a results line"):
        ResultsFile(str(out), resume=True)


def test_out_that_is_a_folder_is_a_usage_error(tmp_path):
    with pytest.raises(UsageError, match="folder"):
        ResultsFile(str(tmp_path), resume=False)


def test_a_second_batch_on_the_same_file_is_refused_until_the_first_closes(tmp_path):
    out = tmp_path / "r.jsonl"
    with ResultsFile(str(out), resume=True) as first:
        first.append(_result("a.pddl"))
        with pytest.raises(UsageError, match="another batch"):
            ResultsFile(str(out), resume=True)
    with ResultsFile(str(out), resume=True) as again:
        assert set(again.latest([os.path.abspath("a.pddl")])) == {os.path.abspath("a.pddl")}


def test_a_line_names_its_problem_absolute_and_relative_to_the_file(tmp_path):
    out = tmp_path / "exp" / "r.jsonl"
    problem = tmp_path / "exp" / "set" / "p1.pddl"
    with ResultsFile(str(out), resume=False) as results:
        results.append(_result(str(problem)))
    record = json.loads(out.read_text())
    assert list(record)[:2] == ["problem", "problem_rel"]
    assert record["problem"] == str(problem) and record["problem_rel"] == "set/p1.pddl"


def test_resume_matches_by_absolute_path_from_any_working_directory(tmp_path, monkeypatch):
    out = tmp_path / "r.jsonl"
    problem = str(tmp_path / "set" / "a.pddl")
    with ResultsFile(str(out), resume=False) as results:
        results.append(_result(problem))
    (tmp_path / "elsewhere").mkdir()
    monkeypatch.chdir(tmp_path / "elsewhere")
    with ResultsFile(str(out), resume=True) as results:
        assert results.latest([problem, str(tmp_path / "set" / "b.pddl")]) == {
            problem: results.records[0]}


def test_a_results_file_moved_with_its_set_matches_by_relative_path(tmp_path):
    old, new = tmp_path / "machine-a" / "exp", tmp_path / "machine-b" / "runs" / "exp"
    with ResultsFile(str(old / "r.jsonl"), resume=False) as results:
        results.append(_result(str(old / "set" / "a.pddl"), cost=1.0))
        # Outside the file's folder: still relative to it.
        results.append(_result(str(old.parent / "common" / "b.pddl"), cost=2.0))
    new.mkdir(parents=True)
    (old / "r.jsonl").rename(new / "r.jsonl")
    moved = [str(new / "set" / "a.pddl"), str(new.parent / "common" / "b.pddl"),
             str(new / "set" / "c.pddl")]
    with ResultsFile(str(new / "r.jsonl"), resume=True) as results:
        latest = results.latest(moved)
    assert {p: r["cost"] for p, r in latest.items()} == {moved[0]: 1.0, moved[1]: 2.0}


def test_absolute_match_wins_over_a_relative_one_and_the_last_line_wins(tmp_path):
    here = tmp_path / "here"
    problem = str(here / "set" / "a.pddl")
    lines = [{"problem": problem, "problem_rel": "set/a.pddl", "status": "crashed"},
             {"problem": problem, "problem_rel": "set/a.pddl", "status": "solved"},
             # From another copy of the set: same relative path, later in the file.
             {"problem": "/gone/set/a.pddl", "problem_rel": "set/a.pddl", "status": "error"}]
    here.mkdir()
    (here / "r.jsonl").write_text("".join(json.dumps(line) + "\n" for line in lines))
    with ResultsFile(str(here / "r.jsonl"), resume=True) as results:
        assert results.latest([problem])[problem]["status"] == "solved"


def test_a_line_without_problem_rel_is_relative_to_the_file(tmp_path, monkeypatch):
    # Written by hand, or by a tampcli that recorded paths as given.
    (tmp_path / "r.jsonl").write_text(json.dumps({"problem": "set/a.pddl"}) + "\n")
    (tmp_path / "cwd").mkdir()
    monkeypatch.chdir(tmp_path / "cwd")
    with ResultsFile(str(tmp_path / "r.jsonl"), resume=True) as results:
        assert set(results.latest([str(tmp_path / "set" / "a.pddl")])) == {
            str(tmp_path / "set" / "a.pddl")}
