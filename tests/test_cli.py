from pathlib import Path

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


def test_an_internal_error_exits_70_with_or_without_its_traceback(monkeypatch, capsys):
    """blind29 (DOC_GAPS 3): with --traceback the exception escaped, exit 1."""
    import tampcli.cli.check as check_cmd
    from tampcli.cli import main

    def broken(args, ui):
        raise ValueError("a bug")

    monkeypatch.setattr(check_cmd, "run", broken)
    root = Path(__file__).resolve().parents[1]
    argv = ["check", str(root / "domains" / "blocksworld" / "domain.pddl"),
            str(root / "problems" / "blocksworld" / "p01.pddl")]
    for extra, shown in (([], False), (["--traceback"], True)):
        assert main(argv + extra) == 70
        err = capsys.readouterr().err
        assert "internal error: ValueError: a bug" in err
        assert ("Traceback (most recent call last)" in err) is shown
