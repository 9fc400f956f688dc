import shutil
from pathlib import Path

import pytest

from tampcli.batch.discover import (
    discover,
    domain_candidates,
    find_domain,
    is_domain_file,
    largest_first,
)
from tampcli.errors import UsageError

from .common import GRIPPER_DOMAIN, GRIPPER_P01, IPC, ROOT, problem_set


def test_psr_small_problem_finds_its_numbered_domain_by_prefix():
    problem = IPC / "psr-small" / "p01-s2-n1-l2-f50.pddl"
    assert find_domain(problem) == IPC / "psr-small" / "p01-domain.pddl"


def test_every_psr_small_and_parcprinter_problem_gets_its_own_domain():
    for name, count in (("psr-small", 15), ("parcprinter-08-strips", 15)):
        jobs = discover([str(IPC / name)])
        assert len(jobs) == count
        for job in jobs:
            number = Path(job.problem).name[:3]
            assert Path(job.domain).name == f"{number}-domain.pddl", job
            assert job.label == name


def test_folder_with_domain_pddl_beside_problems():
    jobs = discover([str(IPC / "gripper")])
    assert len(jobs) == 15
    assert {job.domain for job in jobs} == {str(GRIPPER_DOMAIN)}
    assert all("domain" not in Path(job.problem).name for job in jobs)


def test_natural_order_puts_small_problems_first(tmp_path):
    names = [Path(job.problem).name for job in discover([str(IPC / "blocks")])]
    assert names[:4] == ["probBLOCKS-4-0.pddl", "probBLOCKS-4-1.pddl", "probBLOCKS-4-2.pddl",
                         "probBLOCKS-5-0.pddl"]
    problem_set(tmp_path, ["probBLOCKS-10-0.pddl", "probBLOCKS-9-0.pddl"])
    names = [Path(job.problem).name for job in discover([str(tmp_path)])]
    assert names == ["probBLOCKS-9-0.pddl", "probBLOCKS-10-0.pddl"]


def test_repository_layout_problems_to_domains():
    problem = ROOT / "problems" / "blocksworld" / "p01.pddl"
    assert find_domain(problem).resolve() == (ROOT / "domains" / "blocksworld" / "domain.pddl")


@pytest.mark.parametrize("domain_name", ["domain_p07.pddl", "domain-p07.pddl", "p07-domain.pddl",
                                         "p07_domain.pddl"])
def test_per_problem_domain_names(tmp_path, domain_name):
    shutil.copy(GRIPPER_P01, tmp_path / "p07.pddl")
    shutil.copy(GRIPPER_DOMAIN, tmp_path / domain_name)
    # A generic domain.pddl is there too: the per-problem one wins.
    shutil.copy(IPC / "blocks" / "domain.pddl", tmp_path / "domain.pddl")
    [job] = discover([str(tmp_path)])
    assert job.problem == str(tmp_path / "p07.pddl")
    assert job.domain == str(tmp_path / domain_name)


def test_domain_in_parent_folder(tmp_path):
    (tmp_path / "probs").mkdir()
    shutil.copy(GRIPPER_DOMAIN, tmp_path / "domain.pddl")
    shutil.copy(GRIPPER_P01, tmp_path / "probs" / "a.pddl")
    [job] = discover([str(tmp_path / "probs")])
    assert job.domain == str(tmp_path / "domain.pddl")


def test_problem_without_domain_is_a_job_without_domain(tmp_path):
    shutil.copy(GRIPPER_P01, tmp_path / "lonely.pddl")
    [job] = discover([str(tmp_path / "lonely.pddl")])
    assert job.domain is None
    assert tmp_path / "domain.pddl" in domain_candidates(tmp_path / "lonely.pddl")


def test_domain_files_are_recognised_by_content_then_name(tmp_path):
    assert is_domain_file(GRIPPER_DOMAIN)
    assert not is_domain_file(GRIPPER_P01)
    renamed = tmp_path / "mystery.pddl"
    shutil.copy(GRIPPER_DOMAIN, renamed)
    assert is_domain_file(renamed)
    commented = tmp_path / "c.pddl"
    commented.write_text("; (define (domain x))\n" + GRIPPER_P01.read_text())
    assert not is_domain_file(commented)
    garbage = tmp_path / "domain-x.pddl"
    garbage.write_text("not pddl")
    assert is_domain_file(garbage)
    assert not is_domain_file(tmp_path / "missing-p1.pddl")


def test_shell_glob_with_the_domain_file_keeps_only_problems():
    paths = [str(GRIPPER_DOMAIN), str(GRIPPER_P01), str(GRIPPER_P01)]
    jobs = discover(paths)
    assert [job.problem for job in jobs] == [str(GRIPPER_P01)]


def test_missing_path_and_empty_folder_are_usage_errors(tmp_path):
    with pytest.raises(UsageError, match="no such file"):
        discover([str(tmp_path / "nope")])
    (tmp_path / "empty").mkdir()
    shutil.copy(GRIPPER_DOMAIN, tmp_path / "empty" / "domain.pddl")
    with pytest.raises(UsageError, match="no problem files found"):
        discover([str(tmp_path / "empty")])


def test_hidden_folders_are_not_searched(tmp_path):
    (tmp_path / ".venv" / "pkg").mkdir(parents=True)
    shutil.copy(GRIPPER_DOMAIN, tmp_path / "domain.pddl")
    shutil.copy(GRIPPER_P01, tmp_path / ".venv" / "pkg" / "p.pddl")
    shutil.copy(GRIPPER_P01, tmp_path / "P1.PDDL")
    jobs = discover([str(tmp_path)])
    assert [Path(job.problem).name for job in jobs] == ["P1.PDDL"]


def test_largest_problems_are_run_first():
    jobs = discover([str(IPC / "gripper")])
    ordered = largest_first(jobs)
    sizes = [Path(job.problem).stat().st_size for job in ordered]
    assert sizes == sorted(sizes, reverse=True)
    assert Path(ordered[0].problem).name == "prob15.pddl"
    assert sorted(ordered, key=lambda j: j.problem) == sorted(jobs, key=lambda j: j.problem)
