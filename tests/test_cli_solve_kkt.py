"""The KKT certificate end to end: `solve` writes it in solution.json and `--json`,
shows it in the skeleton lines, and the reader takes it back (or its absence)."""

import copy
import io
import json
import re

import pytest
from rich.console import Console

from tampcli import solution
from tampcli.cli import main
from tampcli.cli.ui import UI
from tampcli.errors import SolutionFileError
from tampcli.solution_kkt import KktStages
from tampcli.solution_read import read_solution
from tests.conftest import ROOT

DOMAIN = ROOT / "domains" / "planar-push" / "domain.pddl"
PROBLEM = ROOT / "problems" / "planar-push" / "p01.pddl"
# SLSQP stops on a relative cost change of 1e-6 (nlp.py's ftol): measured 1.2e-3 on
# the path of p01 (|grad f| 0.14), 3e-5 at ftol 1e-9, 4e-7 at 1e-12.
PATH_STATIONARITY = 1e-2


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    """One solve shared by the tests (the `cli` fixture's runner, module-wide):
    (solution.json's path, its content, stderr)."""
    out_file = tmp_path_factory.mktemp("kkt") / "solution.json"
    out, err = io.StringIO(), io.StringIO()
    ui = UI(Console(file=out, width=200), Console(file=err, width=200))
    code = main(["solve", "--out", str(out_file), str(DOMAIN), str(PROBLEM)], ui)
    assert code == 0, err.getvalue()
    return out_file, json.loads(out_file.read_text()), err.getvalue()


def test_the_answer_has_a_certificate_per_stage(solved):
    _, sol, _ = solved
    kkt = sol["kkt"]
    assert set(kkt) == {"final", "keyframes", "path"}
    for c in kkt.values():
        assert c["dual_feasible"] is True
        assert c["violation"] <= 1e-4
        assert c["complementarity"] <= 1e-6
    assert kkt["keyframes"]["stationarity"] < 1e-8
    path = kkt["path"]
    assert path["stationarity"] < PATH_STATIONARITY
    assert path["nlps"] == 2  # one NLP per motion: to the box, then carrying it
    # The carry goes round the obstacle: its collision rows hold the path, with mu > 0.
    carriers = [a for a in path["active"] if a["multiplier"] > 1e-3]
    assert carriers and all(a["kind"] == "ineq" for a in carriers)
    assert re.fullmatch(r"motion 1 before \(place box goal\): collision planar_body vs "
                        r"obstacle \(margin \d+ mm\)", carriers[0]["name"])
    assert path["min_multiplier"] >= 0.0


def test_each_skeleton_record_holds_the_certificates_of_the_stages_it_solved(solved):
    _, sol, _ = solved
    winner = next(s for s in sol["skeletons"] if s["plan"] == sol["plan"])
    assert winner["kkt"] == sol["kkt"]
    # The push (no face's friction cone reaches the goal) is proved impossible as the
    # box's first move before any skeleton (bnb/lessons.first_move_proofs): it is never
    # drawn, so it has no record (it had one, infeasible before any NLP, without kkt).
    assert sol["stats"]["learning_proved"] >= 1
    assert all(s["plan"] != ["(push box start goal table)"] for s in sol["skeletons"])
    assert all(s["kkt"] == {} for s in sol["skeletons"] if s["stage"] is None)


def test_the_skeleton_lines_and_the_summary_show_it(solved):
    _, sol, err = solved
    stationarity = sol["kkt"]["path"]["stationarity"]
    assert f"kkt {stationarity:.1e}, " in err
    assert "skeleton #1: solved at path, symbolic cost 4," in err
    assert "symbolic cost 2" not in err  # the push: proved impossible, never drawn
    assert re.search(r"KKT path: stationarity \S+ \(\|grad f\| \S+\), complementarity \S+, "
                     r"min multiplier \S+, dual feasible; carried by motion 1 before "
                     r"\(place box goal\): collision planar_body vs obstacle", err), err


def test_solve_json_prints_it(cli):
    run = cli("solve", "--json", DOMAIN, PROBLEM)
    assert run.code == 0, run.err
    kkt = json.loads(run.out)["kkt"]
    assert kkt["path"]["stationarity"] < PATH_STATIONARITY
    assert any("collision planar_body vs obstacle" in a["name"] for a in kkt["path"]["active"])


def test_the_reader_takes_it_back(solved):
    path, sol, _ = solved
    back = read_solution(path).raw
    assert solution.to_dict(back)["kkt"] == sol["kkt"]
    assert back.kkt.path.active[0].name == sol["kkt"]["path"]["active"][0]["name"]
    assert [solution.to_dict(back)["skeletons"][i]["kkt"] for i in range(len(sol["skeletons"]))] \
        == [s["kkt"] for s in sol["skeletons"]]


def _variant(tmp_path, sol, change):
    data = copy.deepcopy(sol)
    change(data)
    path = tmp_path / "variant.json"
    path.write_text(json.dumps(data))
    return path


def test_a_file_without_certificates_is_read(solved, tmp_path):
    _, sol, _ = solved

    def strip(data):
        del data["kkt"]
        for s in data["skeletons"]:
            del s["kkt"]

    back = read_solution(_variant(tmp_path, sol, strip)).raw
    assert back.kkt == KktStages()
    assert all(s.kkt == KktStages() for s in back.skeletons)


@pytest.mark.parametrize("change, key, words", [
    (lambda d: d.update(kkt=[1]), "kkt", "expected an object of stage -> certificate"),
    (lambda d: d["kkt"].update(search={}), "kkt", "expected a stage"),
    (lambda d: d["kkt"]["path"].update(stationarity="small"), "kkt.path.stationarity",
     "expected a number or null"),
    (lambda d: d["kkt"]["path"].update(dual_feasible=1), "kkt.path.dual_feasible",
     "expected true or false"),
    (lambda d: d["kkt"]["path"]["active"][0].update(kind="contact"),
     "kkt.path.active[0].kind", "expected one of eq, ineq, bound"),
    # (the winner is the first record: the push is proved impossible before any is drawn)
    (lambda d: d["skeletons"][0]["kkt"]["final"].update(nlps=0), "skeletons[0].kkt.final.nlps",
     "expected a count >= 1"),
])
def test_a_bad_certificate_is_located(solved, tmp_path, change, key, words):
    _, sol, _ = solved
    path = _variant(tmp_path, sol, change)
    with pytest.raises(SolutionFileError) as info:
        read_solution(path)
    text = info.value.render()
    assert text.startswith(f"{path}: {key}: ") and words in text, text


def test_docs_name_every_key_of_a_certificate(solved):
    _, sol, _ = solved
    text = (ROOT / "docs" / "formats.md").read_text()
    section = text[text.index("**KKT certificates.**"):]
    table = section[section.index("| key | value |"):]
    table = table[:table.index("\n\n")]
    documented = re.findall(r"^\| `(\w+)` \|", table, re.MULTILINE)
    assert documented == list(sol["kkt"]["path"])
