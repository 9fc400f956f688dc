"""The lifted plan validator against real planners' plans and unified-planning's validator.

Plans come from Fast Downward (the up-fast-downward build) and pyperplan,
run here; unified-planning is the second opinion wherever it reads the domain.
"""

from __future__ import annotations

import re
import subprocess
import sys
from functools import cache
from pathlib import Path

import pytest

from tampcli.pddl import parser
from tampcli.search.plan_text import PlanStep, PlanSyntaxError, parse_plan
from tampcli.search.validate import validate_plan, validate_plan_file
from tests.search.ipc_oracle import domain_of, problems, up_verdict

DOMAINS = ["gripper", "blocks", "logistics00", "miconic-fulladl", "briefcaseworld", "assembly",
           "psr-small", "psr-large", "elevators-opt08-strips"]

CASES = [pytest.param(d, i, id=f"{d}-{i + 1}",
                      marks=() if i == 0 else pytest.mark.slow)
         for d in DOMAINS for i in range(3)]


@cache
def parsed(problem: Path):
    return parser.parse_domain_file(domain_of(problem)), parser.parse_problem_file(problem)


@cache
def fd_plan(problem: Path, tmp: Path) -> tuple[list[str], float]:
    """A (not necessarily optimal) plan by Fast Downward, and the cost it reports."""
    import up_fast_downward

    fd = Path(up_fast_downward.__file__).parent / "downward" / "fast-downward.py"
    plan_file = tmp / f"{problem.parent.name}-{problem.stem}.plan"
    subprocess.run([sys.executable, str(fd), "--plan-file", str(plan_file),
                    str(domain_of(problem)), str(problem), "--search", "eager_greedy([ff()])"],
                   cwd=tmp, capture_output=True, check=True, timeout=120)
    text = plan_file.read_text()
    cost = float(re.search(r"cost = (\S+)", text).group(1))
    return [line for line in text.splitlines() if line.startswith("(")], cost


@pytest.fixture(scope="module")
def tmp(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("plans")


@pytest.mark.parametrize("domain,index", CASES)
def test_accepts_fast_downward_plans(domain, index, tmp):
    problem = problems(domain)[index]
    plan, cost = fd_plan(problem, tmp)
    report = validate_plan(*parsed(problem), plan)
    assert report.valid, report.failure
    assert report.cost == cost
    assert report.steps == len(plan)
    verdict = up_verdict(problem, plan)
    if verdict is not None:
        up_valid, up_cost, _ = verdict
        assert up_valid
        if up_cost is not None:
            assert up_cost == cost


def mutations(plan: list[str], objects: list[str]):
    """(name, mutated plan) triples: swap two neighbours, drop one, change an object."""
    n = len(plan)
    for i in sorted({0, n // 2, n - 2}):
        if 0 <= i < n - 1 and plan[i] != plan[i + 1]:
            yield f"swap{i}", plan[:i] + [plan[i + 1], plan[i]] + plan[i + 2:]
    for i in sorted({0, n // 2, n - 1}):
        yield f"drop{i}", plan[:i] + plan[i + 1:]
    for i in sorted({0, n // 2}):
        step = plan[i].strip("()").split()
        if len(step) > 1:
            other = next(o for o in objects if o != step[-1])
            yield f"object{i}", plan[:i] + ["(" + " ".join(step[:-1] + [other]) + ")"] + plan[i + 1:]


# unified-planning takes about a second per plan: two domains in the fast suite
MUTATION_CASES = [pytest.param(d, i, id=f"{d}-{i + 1}",
                               marks=() if (i == 0 and d in ("miconic-fulladl",
                                                             "psr-large"))
                               else pytest.mark.slow)
                  for d in DOMAINS for i in range(3)]


@pytest.mark.parametrize("domain,index", MUTATION_CASES)
def test_rejects_mutated_plans_at_the_step_unified_planning_finds(domain, index, tmp):
    problem = problems(domain)[index]
    plan, _ = fd_plan(problem, tmp)
    if up_verdict(problem, plan) is None:
        pytest.skip("unified-planning cannot read this domain")
    dom, prob = parsed(problem)
    objects = [o.name for o in prob.objects]
    checked = 0
    for name, mutated in mutations(plan, objects):
        report = validate_plan(dom, prob, mutated)
        up_valid, _, up_failing = up_verdict(problem, mutated)
        assert report.valid == up_valid, name
        if up_failing == "ill-typed":
            assert name.startswith("object"), name
            assert report.failure.step == int(name[len("object"):]) + 1
            assert "must be of type" in report.failure.reason
        elif up_failing is not None:
            assert report.failure.step == up_failing + 1, (name, report.failure)
            checked += 1
        elif not report.valid:
            assert report.failure.step is None, (name, report.failure)
    assert checked > 0 or len(plan) < 3


def grounded_failing_step(problem: Path, plan: list[str]):
    """First inapplicable step (1-based), or None if the goal fails, or "valid": via grounding."""
    from tampcli.task.ground import ground

    task = ground(*parsed(problem))
    by_name = {op.name: op for op in task.operators}
    state = task.init
    for i, name in enumerate(plan, start=1):
        op = by_name.get("(" + " ".join(name.strip("()").split()) + ")")
        if op is None or op not in task.applicable(state):
            return i
        state = task.apply(state, op)
    return "valid" if task.is_goal(state) else None


@pytest.mark.parametrize("domain,index", [c for c in MUTATION_CASES if c.values[0] == "psr-large"])
def test_mutations_with_derived_predicates_fail_where_grounding_says(domain, index, tmp):
    problem = problems(domain)[index]
    plan, _ = fd_plan(problem, tmp)
    dom, prob = parsed(problem)
    for name, mutated in mutations(plan, [o.name for o in prob.objects]):
        report = validate_plan(dom, prob, mutated)
        expected = grounded_failing_step(problem, mutated)
        if expected == "valid":
            assert report.valid, name
        else:
            assert report.failure.step == expected, (name, report.failure)


# ---------------------------------------------------------------- hand-written cases

DOMAIN = """
(define (domain toy)
  (:requirements :adl :derived-predicates :action-costs)
  (:types block - object table - object)
  (:constants t0 - table)
  (:predicates (on ?b - block ?x - object) (clear ?x - object) (holding ?b - block)
               (handempty) (above ?a - block ?b - object) (tidy))
  (:functions (total-cost) - number (weight ?b - block) - number)
  (:derived (above ?a - block ?b - object) (on ?a ?b))
  (:derived (above ?a - block ?b - object)
            (exists (?c - block) (and (on ?a ?c) (above ?c ?b))))
  (:derived (tidy) (forall (?b - block) (not (holding ?b))))
  (:action pick
    :parameters (?b - block ?x - object)
    :precondition (and (on ?b ?x) (clear ?b) (handempty) (not (= ?b ?x)))
    :effect (and (holding ?b) (clear ?x) (not (on ?b ?x)) (not (clear ?b)) (not (handempty))
                 (increase (total-cost) (weight ?b))))
  (:action put
    :parameters (?b - block ?x - object)
    :precondition (and (holding ?b) (or (clear ?x) (= ?x t0)))
    :effect (and (on ?b ?x) (handempty) (clear ?b) (not (holding ?b))
                 (when (not (= ?x t0)) (not (clear ?x)))
                 (increase (total-cost) 1)))
  (:action sweep
    :parameters ()
    :precondition (tidy)
    :effect (and (forall (?b - block) (when (on ?b t0) (clear ?b)))
                 (increase (total-cost) 0)))
  (:action flip
    :parameters ()
    :precondition ()
    :effect (and (when (handempty) (not (handempty))) (when (not (handempty)) (handempty))))
  (:action refresh
    :parameters (?b - block)
    :precondition ()
    :effect (and (not (clear ?b)) (clear ?b))))
"""

PROBLEM = """
(define (problem toy1) (:domain toy)
  (:objects a b c - block)
  (:init (on a t0) (on b a) (on c t0) (clear b) (clear c) (clear t0) (handempty)
         (= (weight a) 5) (= (weight b) 2) (= (weight c) 3) (= (total-cost) 0))
  (:goal (and (above c a) (tidy)))
  (:metric minimize (total-cost)))
"""


@pytest.fixture
def toy():
    return parser.parse_domain(DOMAIN), parser.parse_problem(PROBLEM)


def test_costs_use_static_function_terms(toy):
    report = validate_plan(*toy, ["(pick c t0)", "(put c b)", "(sweep)"])
    assert report.valid, report.failure
    assert report.cost == 3 + 1 + 0
    assert not report.unit_cost


def test_derived_predicate_recursion_reaches_the_goal(toy):
    # c on b on a: (above c a) holds only through the recursive axiom
    assert validate_plan(*toy, ["(pick c t0)", "(put c b)"]).valid


def test_goal_failure_names_the_false_part(toy):
    report = validate_plan(*toy, ["(pick c t0)"])
    assert not report.valid and report.failure.step is None
    assert "(above c a) is false" in report.failure.reason
    assert "(tidy) is false" in report.failure.reason


def test_precondition_failure_names_the_conjunct(toy):
    report = validate_plan(*toy, ["(pick a t0)"])
    assert report.failure.step == 1
    assert report.failure.reason == "precondition (clear a) is false"


def test_equality_and_negation_in_preconditions(toy):
    report = validate_plan(*toy, ["(pick c t0)", "(put c c)"])
    assert report.failure.step == 2
    assert "(or (clear c) (= c t0)) is false" in report.failure.reason


def test_conditional_effect_deletes(toy):
    report = validate_plan(*toy, ["(pick c t0)", "(put c b)", "(pick b a)"])
    assert report.failure.step == 3
    assert report.failure.reason == "precondition (clear b) is false"


def test_conditional_effects_read_the_state_before(toy):
    # read sequentially, flip would delete then re-add (handempty)
    report = validate_plan(*toy, ["(flip)", "(pick c t0)"])
    assert report.failure.step == 2
    assert report.failure.reason == "precondition (handempty) is false"
    assert validate_plan(*toy, ["(flip)", "(flip)", "(pick c t0)", "(put c b)"]).valid


def test_add_wins_over_delete_of_the_same_fact(toy):
    assert validate_plan(*toy, ["(refresh c)", "(pick c t0)", "(put c b)"]).valid


def test_unknown_action_object_arity_and_type(toy):
    dom, prob = toy
    cases = {
        "(fly c t0)": "unknown action fly",
        "(pick c)": "pick takes 2 argument(s), the plan gives 1",
        "(pick c zz)": "unknown object zz",
        "(pick t0 c)": "object t0 is of type table, ?b must be of type block",
    }
    for step, reason in cases.items():
        report = validate_plan(dom, prob, [step])
        assert not report.valid and report.failure.step == 1
        assert reason in report.failure.reason, report.failure


def test_plan_file_gives_lines_and_declared_cost(toy, tmp_path):
    path = tmp_path / "p.plan"
    path.write_text("; a comment\n(pick c t0)\n\n(PUT c B) ; capitals are fine\n"
                    "; cost = 4 (general cost)\n")
    report = validate_plan_file(*toy, path)
    assert report.valid and report.cost == report.declared_cost == 4
    path.write_text("(pick c t0)\n(put c t0)\n(pick a t0)\n")
    report = validate_plan_file(*toy, path)
    assert report.failure.step == 3 and report.failure.line == 3
    assert "line 3" in report.failure.describe()


@pytest.mark.parametrize("text,line,column,words", [
    ("(pick a\n", 2, 1, "not closed"),
    ("(pick a t0))\n", 1, 12, 'unexpected ")"'),
    ("(pick (a) t0)\n", 1, 7, "do not nest"),
    ("pick a t0\n", 1, 1, "outside a step"),
    ("(pick a t0)\n()\n", 2, 2, "empty step"),
])
def test_bad_plan_syntax_is_located(text, line, column, words):
    with pytest.raises(PlanSyntaxError) as err:
        parse_plan(text, "x.plan")
    assert (err.value.path, err.value.line, err.value.column) == ("x.plan", line, column)
    assert words in err.value.message


def test_planner_decorations_are_accepted():
    parsed_plan = parse_plan("0: (pick a t0)\n1.000: (put a b) [1.000]\n")
    assert parsed_plan.steps == (PlanStep("pick", ("a", "t0"), 1, 4),
                                 PlanStep("put", ("a", "b"), 2, 8))


@pytest.mark.parametrize("wrap", ["(and {})", "(or (q ?x) {})", "(not (not {}))"])
def test_deeply_nested_preconditions(wrap):
    # deeper than Python's own parser takes: evaluated node by node instead
    pre = "(p ?x)"
    for _ in range(120):
        pre = wrap.format(pre)
    dom = parser.parse_domain("(define (domain d) (:predicates (p ?x) (q ?x)) (:action a "
                              f":parameters (?x) :precondition {pre} :effect (q ?x)))")
    for init, valid in (("(p o)", True), ("", False)):
        prob = parser.parse_problem(f"(define (problem x) (:domain d) (:objects o) "
                                    f"(:init {init}) (:goal (q o)))")
        report = validate_plan(dom, prob, ["(a o)"])
        assert report.valid is valid
        if not valid:
            assert report.failure.step == 1
