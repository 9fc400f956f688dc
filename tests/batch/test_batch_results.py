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
    out.write_text(json.dumps({"problem": "a.pddl"}) + "\n")
    with pytest.raises(UsageError, match="--resume"):
        ResultsFile(str(out), resume=False)
    with ResultsFile(str(out), resume=True) as results:
        assert results.done() == {os.path.abspath("a.pddl")}


def test_torn_last_line_is_cut_on_resume(tmp_path):
    out = tmp_path / "r.jsonl"
    good = json.dumps(_result("a.pddl").to_json()) + "\n"
    torn = json.dumps(_result("b.pddl").to_json())[:37]
    out.write_text(good + torn)
    with ResultsFile(str(out), resume=True) as results:
        assert results.repaired_bytes == len(torn)
        assert results.done() == {os.path.abspath("a.pddl")}
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
        assert again.done() == {os.path.abspath("a.pddl")}
