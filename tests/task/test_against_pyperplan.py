"""Oracle: pyperplan's grounding, explored exhaustively, applies the same operators."""

import logging

import pytest

from tests.task.tasks import IPC, ipc_task

planner = pytest.importorskip("pyperplan.planner")
grounding = pytest.importorskip("pyperplan.grounding")


def _ours(task):
    seen, stack, used = {task.init}, [task.init], set()
    while stack:
        for op, succ in task.successors(stack.pop()):
            used.add(op.name)
            if succ not in seen:
                seen.add(succ)
                stack.append(succ)
    return len(seen), used


def _pyperplan(domain, problem):
    logging.disable(logging.CRITICAL)
    task = grounding.ground(planner._parse(str(domain), str(problem)),
                            remove_irrelevant_operators=False)
    seen, stack, used = {task.initial_state}, [task.initial_state], set()
    while stack:
        for op, succ in task.get_successor_states(stack.pop()):
            used.add(op.name)
            if succ not in seen:
                seen.add(succ)
                stack.append(succ)
    return len(seen), used


@pytest.mark.parametrize("domain,problem", [
    ("blocks", "probBLOCKS-4-0.pddl"),
    ("gripper", "prob01.pddl"),
    ("miconic", "s2-0.pddl"),
    ("visitall-opt11-strips", "problem03-full.pddl"),
    ("psr-small", "p01-s2-n1-l2-f50.pddl"),
    ("driverlog", "p01.pddl"),
    ("satellite", "p01-pfile1.pddl"),
    ("depot", "p01.pddl"),
])
def test_same_reachable_states_and_applied_operators(domain, problem):
    folder = IPC / domain
    domain_file = folder / "domain.pddl"
    if not domain_file.exists():
        domain_file = folder / (problem.split("-")[0] + "-domain.pddl")
    n_ours, ops_ours = _ours(ipc_task(domain, problem))
    n_theirs, ops_theirs = _pyperplan(domain_file, folder / problem)
    assert n_ours == n_theirs
    assert ops_ours == ops_theirs
