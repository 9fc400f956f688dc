"""Every IPC file parses, passes the semantic checks, and prints back to an equal tree."""

import pytest

from tampcli.pddl import check, parser, printer
from tests.pddl import ipc

FIRST = ipc.pairs(first=3)
ALL = ipc.pairs()


def _ids(pairs):
    return [f"{p.parent.name}/{p.name}" for _, p in pairs]


def _check_pair(domain_path, problem_path):
    domain = parser.parse_domain_file(domain_path)
    problem = parser.parse_problem_file(problem_path)
    assert problem.domain_name == domain.name
    assert domain.actions
    assert check.check(domain, problem) == []
    return domain, problem


def test_pairing_finds_per_problem_domains():
    by_problem = {p.name: d.name for d, p in ALL if p.parent.name in ("psr-small",
                                                                      "parcprinter-08-strips")}
    assert by_problem["p01-s2-n1-l2-f50.pddl"] == "p01-domain.pddl"
    assert by_problem["p01.pddl"] == "p01-domain.pddl"
    assert len(ALL) == sum(1 for _ in ipc.IPC.rglob("*.pddl")) - len(
        [p for p in ipc.IPC.rglob("*.pddl") if ipc.is_domain_file(p)])


@pytest.mark.parametrize("domain_path, problem_path", FIRST, ids=_ids(FIRST))
def test_first_problems_parse_and_check(domain_path, problem_path):
    _check_pair(domain_path, problem_path)


@pytest.mark.slow
@pytest.mark.parametrize("domain_path, problem_path", ALL, ids=_ids(ALL))
def test_all_problems_parse_and_check(domain_path, problem_path):
    _check_pair(domain_path, problem_path)


def _round_trip(path):
    tree = parser.parse(path.read_text(), str(path))
    again = parser.parse(printer.to_pddl(tree))
    assert again == tree
    assert printer.to_pddl(again) == printer.to_pddl(tree)


ROUND_TRIP = sorted({d for d, _ in FIRST} | {d / "domain.pddl" for d in ipc.domains()
                                             if (d / "domain.pddl").is_file()}
                    | {p for _, p in FIRST})


@pytest.mark.parametrize("path", ROUND_TRIP, ids=[f"{p.parent.name}/{p.name}" for p in ROUND_TRIP])
def test_round_trip(path):
    _round_trip(path)


ALL_FILES = sorted(ipc.IPC.rglob("*.pddl"))


@pytest.mark.slow
@pytest.mark.parametrize("path", ALL_FILES, ids=[f"{p.parent.name}/{p.name}" for p in ALL_FILES])
def test_round_trip_all(path):
    _round_trip(path)
