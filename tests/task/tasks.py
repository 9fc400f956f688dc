"""Tiny hand-written PDDL tasks shared by the task and search tests."""

from __future__ import annotations

from pathlib import Path

from tampcli.pddl import parser
from tampcli.task.ground import ground

IPC = Path(__file__).resolve().parents[2] / "benchmarks" / "ipc"


def make_task(domain: str, problem: str):
    return ground(parser.parse_domain(domain), parser.parse_problem(problem))


def ipc_task(domain_dir: str, problem: str):
    folder = IPC / domain_dir
    domain = folder / "domain.pddl"
    if not domain.exists():
        domain = folder / (problem.split(".")[0].split("-")[0] + "-domain.pddl")
    return ground(parser.parse_domain_file(domain), parser.parse_problem_file(folder / problem))


def replay(task, plan) -> frozenset:
    """The state a plan reaches; asserts every step is applicable."""
    state = task.init
    for op in plan:
        assert op in task.applicable(state), f"{op.name} not applicable"
        state = task.apply(state, op)
    return state


def by_name(task, name: str):
    op = task.operator(name)
    assert op is not None, f"no operator {name}"
    return op


def facts(task, state) -> set[str]:
    return {task.facts[i] for i in task.closure(state)}


# A corridor of rooms; moving needs a static link; the goal is a room.
CORRIDOR = """
(define (domain corridor)
  (:requirements :strips :typing :equality)
  (:types room)
  (:predicates (at ?r - room) (link ?a ?b - room) (visited ?r - room))
  (:action move
    :parameters (?from ?to - room)
    :precondition (and (at ?from) (link ?from ?to) (not (= ?from ?to)))
    :effect (and (at ?to) (visited ?to) (not (at ?from)))))
"""


def corridor_problem(n: int, goal: str | None = None) -> str:
    rooms = " ".join(f"r{i}" for i in range(n))
    links = " ".join(f"(link r{i} r{i + 1}) (link r{i + 1} r{i})" for i in range(n - 1))
    goal = goal or f"(at r{n - 1})"
    return f"""(define (problem c{n}) (:domain corridor)
  (:objects {rooms} - room)
  (:init (at r0) {links})
  (:goal {goal}))"""


# Lights toggled by one conditional-effect action; the goal needs both on.
ADL_FREE_TOGGLE = ("""
(define (domain lights)
  (:requirements :adl)
  (:types light)
  (:predicates (on ?l - light))
  (:action toggle :parameters (?l - light)
    :precondition (and)
    :effect (and (when (on ?l) (not (on ?l))) (when (not (on ?l)) (on ?l)))))
""", """(define (problem l) (:domain lights) (:objects a b - light) (:init (on a))
  (:goal (and (on a) (on b))))""")
