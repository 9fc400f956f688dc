from tests.conftest import ROOT

BW = ROOT / "domains" / "blocksworld" / "domain.pddl"
BW1 = ROOT / "problems" / "blocksworld" / "p01.pddl"


def test_check_prints_summary(cli):
    run = cli("check", BW, BW1)
    assert run.code == 0, run.err
    assert "blocksworld" in run.out


def test_missing_file_is_bad_input(cli, tmp_path):
    run = cli("check", tmp_path / "nope.pddl")
    assert run.code == 2
    assert "file not found" in run.err
    assert "Traceback" not in run.err


def test_unknown_flag_is_usage_error(cli):
    run = cli("check", "--frobnicate", BW)
    assert run.code == 2
    assert "unrecognized arguments" in run.err


def test_syntax_error_points_at_line_and_column(cli, tmp_path):
    bad = tmp_path / "bad.pddl"
    bad.write_text("(define (domain d)\n  (:predicates (p ?x))\n  (:action a :parameters (?x) :effect (p ?x) %))\n")
    run = cli("check", bad)
    assert run.code == 2
    assert f"{bad}:3:46:" in run.err
    assert "^" in run.err
