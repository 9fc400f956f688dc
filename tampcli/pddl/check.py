"""Semantic checks of a parsed domain (and problem): names, arities, types, scopes.

`check` raises a PDDLSemanticError at the first mistake, pointing at the
offending place in its file, and an UnsupportedFeatureError at the first use
of a requirement outside the accepted fragment (requirements.py says which
are refused and which only warned about); what is suspicious but accepted
(requirements used but not declared, or declared and ignored...) comes back
as warnings, each `path:line:col: text`.
"""

from __future__ import annotations

from dataclasses import dataclass

from tampcli.errors import UnsupportedFeatureError
from tampcli.pddl import ast
from tampcli.pddl import requirements as reqs
from tampcli.pddl.check_source import Source, located
from tampcli.pddl.requirements import COST
from tampcli.pddl.types import OBJECT, TypeHierarchy


def check(domain: ast.Domain, problem: ast.Problem | None = None) -> list[str]:
    """Raise an InputError on the first error; return warnings."""
    report = reqs.report(domain, problem)
    dom = _DomainChecker(domain)
    _refuse_unsupported(report, "domain", dom.src)
    dom.run()
    if problem is not None:
        checker = _ProblemChecker(dom, problem)
        _refuse_unsupported(report, "problem", checker.src)
        checker.run()
    return dom.warnings + _requirement_warnings(report, domain, problem)


def requirements(domain: ast.Domain, problem: ast.Problem | None = None) -> reqs.RequirementReport:
    """Requirements declared (as written) and used, for the `check` summary."""
    return reqs.report(domain, problem)


def _refuse_unsupported(report: reqs.RequirementReport, which: str, src: Source) -> None:
    # Only numeric fluents get this far: the other unsupported requirements
    # have no place in the AST and were refused while parsing.
    for requirement, span, where in report.unsupported:
        if where == which:
            raise src.error(f"{reqs.describe(requirement)} beyond action costs are not "
                            f"supported: only ({COST}) can be increased or minimized "
                            f"(requirement {requirement})", span, 0, UnsupportedFeatureError)


def _requirement_warnings(report: reqs.RequirementReport, domain: ast.Domain,
                          problem: ast.Problem | None) -> list[str]:
    def where(span, which):
        return located(domain.path if which == "domain" else problem.path, span)

    warnings = [f"{where(span, which)}: unknown requirement {r}"
                for r, span, which in report.unknown]
    for requirement, span, which in report.ignored:
        if requirement in reqs.COST_ONLY and ":action-costs" in report.used:
            text = (f"declares {requirement}, which tampcli supports only as action costs; "
                    "here the functions are only action costs, so they are read as such")
        else:
            text = (f"declares {requirement} ({reqs.describe(requirement)}), which tampcli "
                    "does not support; nothing uses it, so it is ignored")
        warnings.append(f"{where(span, which)}: {text}")
    for requirement, span, which in report.missing:
        warnings.append(f"{where(span, which)}: uses {reqs.describe(requirement)} "
                        f"without declaring {requirement}")
    return warnings




@dataclass(frozen=True)
class _Scope:
    """Variables bound at a point of a formula, and what they are bound by."""

    variables: dict[str, tuple[str, ...]]
    owner: str  # "action move", "derived predicate p", "the goal"


class _DomainChecker:
    def __init__(self, domain: ast.Domain):
        self.domain = domain
        self.src = Source(domain.path)
        self.hierarchy = TypeHierarchy.of(domain)
        self.predicates: dict[str, ast.PredicateDef] = {}
        self.functions: dict[str, ast.FunctionDef] = {}
        self.constants: dict[str, tuple[str, ...]] = {}
        self.derived = frozenset(axiom.name for axiom in domain.axioms)
        self.declared_types: frozenset[str] = frozenset({OBJECT})
        self.warnings: list[str] = []

    def run(self) -> None:
        d = self.domain
        self._types()
        constants: dict[str, ast.Typed] = {}
        for typed in d.constants:
            self._duplicate(constants, typed.name, typed.span, "constant")
            self._declared_types(typed)
            constants[typed.name] = typed
            self.constants[typed.name] = typed.types
        for pred in d.predicates:
            self._duplicate(self.predicates, pred.name, pred.span, "predicate")
            # Parameter names in a declaration only document it (IPC
            # logistics declares `(in ?obj ?obj)`), so they may repeat.
            self._params(pred.params, f"predicate {pred.name}", unique=False)
            self.predicates[pred.name] = pred
        for function in d.functions:
            self._duplicate(self.functions, function.name, function.span, "function")
            self._params(function.params, f"function {function.name}", unique=False)
            self.functions[function.name] = function
        # The axioms first: a derived predicate left out of :predicates is named where it
        # is derived, not as an undeclared predicate where an action uses it (blind20).
        for axiom in d.axioms:
            self._axiom(axiom)
        actions: dict[str, ast.Action] = {}
        for action in d.actions:
            self._duplicate(actions, action.name, action.span, "action")
            actions[action.name] = action
            scope = self._params(action.params, f"action {action.name}")
            self.formula(action.precondition, scope, self.constants, self.src)
            self._effect(action.effect, scope)

    # ---- declarations

    def _types(self) -> None:
        # A type declared twice is a subtype of every parent it is given, as
        # in Fast Downward's translator (IPC storage declares `area` under
        # `object` and again under `surface`); ambiguous, so it is warned about.
        seen: dict[str, ast.Typed] = {}
        for typed in self.domain.types:
            first = seen.get(typed.name)
            if first is not None:
                parents = sorted({*first.types, *typed.types})
                self.warnings.append(
                    f"{located(self.domain.path, typed.span)}: type {typed.name} is declared "
                    f"again (first on line {first.span.line}); it is read as a subtype of "
                    f"{' and '.join(parents)}")
                continue
            seen[typed.name] = typed
        for typed in self.domain.types:
            if typed.name in typed.types and typed.name != OBJECT:
                # The names swept under it with it are what the author most likely did
                # not mean (blind18: `crate place bay park - place` made crates places).
                swept = [t.name for t in self.domain.types
                         if t.name != typed.name and typed.name in t.types]
                under = (f", and {', '.join(swept)} as "
                         f"{'subtypes' if len(swept) > 1 else 'a subtype'} of {typed.name}"
                         if swept else "")
                self.warnings.append(
                    f"{located(self.domain.path, typed.span)}: type {typed.name} is declared "
                    f"a subtype of itself (in `{typed.name} ... - {typed.name}`, every name "
                    f"before the dash is a subtype of the type after it); it is read as a "
                    f"subtype of object{under}")
            for parent in typed.types:
                if parent != OBJECT and parent not in seen:
                    raise self.src.error(f"type {typed.name} has an undeclared parent type "
                                         f"{parent}", typed.span)
        for name in self.hierarchy.cyclic:
            raise self.src.error(f"type {name} is its own ancestor (a cycle in :types)",
                                 seen[name].span)
        self.declared_types = frozenset(seen) | {OBJECT}

    def _declared_types(self, typed: ast.Typed, src: Source | None = None) -> None:
        for t in typed.types:
            if t not in self.declared_types:
                hint = "" if self.domain.types else " (the domain declares no :types)"
                raise (src or self.src).error(f"{typed.name}: undeclared type {t}{hint}",
                                              typed.span)

    def _params(self, params, owner: str, outer: _Scope | None = None,
                src: Source | None = None, unique: bool = True) -> _Scope:
        variables = dict(outer.variables) if outer else {}
        seen: set[str] = set()
        for typed in params:
            if typed.name in seen and unique:
                raise (src or self.src).error(f"duplicate parameter {typed.name} in {owner}",
                                              typed.span)
            seen.add(typed.name)
            self._declared_types(typed, src)
            variables[typed.name] = typed.types
        return _Scope(variables, outer.owner if outer else owner)

    def _duplicate(self, table: dict, name: str, span: ast.Span, what: str) -> None:
        """`table` maps the names seen so far to their nodes."""
        if name in table:
            first = table[name].span.line
            where = f" (first declared on line {first})" if first else ""
            raise self.src.error(f"duplicate {what} {name}{where}", span)

    # ---- formulas and effects

    def formula(self, f: ast.Formula, scope: _Scope, objects: dict, src: Source) -> None:
        if isinstance(f, ast.Atom):
            self.atom(f, scope, objects, src)
        elif isinstance(f, ast.Not):
            self.formula(f.part, scope, objects, src)
        elif isinstance(f, (ast.And, ast.Or)):
            for part in f.parts:
                self.formula(part, scope, objects, src)
        elif isinstance(f, ast.Imply):
            self.formula(f.antecedent, scope, objects, src)
            self.formula(f.consequent, scope, objects, src)
        elif isinstance(f, (ast.Exists, ast.Forall)):
            inner = self._params(f.params, scope.owner, scope, src)
            self.formula(f.body, inner, objects, src)

    def atom(self, atom: ast.Atom, scope: _Scope, objects: dict, src: Source) -> None:
        if atom.predicate == "=":
            if len(atom.args) != 2:
                raise src.error(f"`=` takes 2 arguments, found {len(atom.args)}", atom.span)
            for i, arg in enumerate(atom.args, 1):
                self._arg_types(arg, i, atom.span, scope, objects, src)
            return
        pred = self.predicates.get(atom.predicate)
        if pred is None:
            raise src.error(f"undeclared predicate {atom.predicate}", atom.span, 0)
        self._args(atom.predicate, pred.params, atom.args, atom.span, scope, objects, src,
                   "predicate")

    def _args(self, name, params, args, span, scope, objects, src, what) -> None:
        if len(args) != len(params):
            signature = "".join(f" {p.name}" + ("" if p.types == (OBJECT,) else
                                                 f" - {_type_text(p.types)}") for p in params)
            plural = "" if len(params) == 1 else "s"
            raise src.error(f"{what} {name} takes {len(params)} argument{plural}, found "
                            f"{len(args)}; declared as ({name}{signature})", span,
                            len(params) + 1 if len(args) > len(params) else None)
        for i, (arg, param) in enumerate(zip(args, params, strict=True), 1):
            types = self._arg_types(arg, i, span, scope, objects, src)
            strict = not arg.startswith("?")
            ok = (self.hierarchy.fits(types, param.types) if strict
                  else self.hierarchy.may_fit(types, param.types))
            if not ok:
                raise src.error(f"argument {i} of {name}: {arg} is of type {_type_text(types)}, "
                                f"expected {_type_text(param.types)}", span, i)

    def _arg_types(self, arg, i, span, scope: _Scope, objects: dict, src: Source):
        if arg.startswith("?"):
            if arg not in scope.variables:
                raise src.error(f"free variable {arg}: not a parameter of {scope.owner} nor "
                                "bound by an enclosing forall/exists", span, i)
            return scope.variables[arg]
        if arg not in objects:
            what = "constant" if objects is self.constants else "object or constant"
            raise src.error(f"unknown {what} {arg}", span, i)
        return objects[arg]

    def _effect(self, effect: ast.Effect, scope: _Scope) -> None:
        if isinstance(effect, ast.AndEffect):
            for part in effect.parts:
                self._effect(part, scope)
        elif isinstance(effect, ast.ForallEffect):
            self._effect(effect.body, self._params(effect.params, scope.owner, scope))
        elif isinstance(effect, ast.WhenEffect):
            self.formula(effect.condition, scope, self.constants, self.src)
            self._effect(effect.body, scope)
        elif isinstance(effect, ast.Literal):
            atom = effect.atom
            if atom.predicate == "=":
                raise self.src.error("`=` cannot be an effect", atom.span)
            if atom.predicate in self.derived:
                raise self.src.error(f"derived predicate {atom.predicate} cannot be changed by "
                                     "an effect", atom.span, 0)
            self.atom(atom, scope, self.constants, self.src)
        elif isinstance(effect, ast.Increase):
            self._increase(effect, scope)

    def _increase(self, effect: ast.Increase, scope: _Scope) -> None:
        self.function_term(effect.function, scope, self.constants, self.src)
        amount = effect.amount
        if isinstance(amount, ast.FunctionTerm):
            if amount.name == COST:
                raise self.src.error(f"an action cost must be a number or a static function, "
                                     f"not ({COST})", amount.span, 0)
            self.function_term(amount, scope, self.constants, self.src)
        elif amount < 0:
            raise self.src.error(f"negative action cost {amount:g}", effect.span, 2)

    def function_term(self, term: ast.FunctionTerm, scope, objects, src) -> None:
        function = self.functions.get(term.name)
        if function is None:
            hint = " (declare it in :functions)" if term.name == COST else ""
            raise src.error(f"undeclared function {term.name}{hint}", term.span, 0)
        self._args(term.name, function.params, term.args, term.span, scope, objects, src,
                   "function")

    def _axiom(self, axiom: ast.Axiom) -> None:
        pred = self.predicates.get(axiom.name)
        if pred is None:
            raise self.src.error(f"derived predicate {axiom.name} is not declared in "
                                 ":predicates", axiom.span, 1)
        if len(axiom.params) != len(pred.params):
            raise self.src.error(f"derived predicate {axiom.name} takes {len(pred.params)} "
                                 f"arguments, found {len(axiom.params)}", axiom.span, 1)
        scope = self._params(axiom.params, f"derived predicate {axiom.name}")
        for i, (param, declared) in enumerate(zip(axiom.params, pred.params, strict=True), 1):
            if not self.hierarchy.may_fit(param.types, declared.types):
                raise self.src.error(f"argument {i} of derived predicate {axiom.name}: "
                                     f"{param.name} is of type {_type_text(param.types)}, "
                                     f"declared as {_type_text(declared.types)}", param.span)
        self.formula(axiom.body, scope, self.constants, self.src)


# ---------------------------------------------------------------- problem


class _ProblemChecker:
    def __init__(self, dom: _DomainChecker, problem: ast.Problem):
        self.dom, self.problem = dom, problem
        self.src = Source(problem.path)

    def run(self) -> None:
        p, dom = self.problem, self.dom
        if p.domain_name != dom.domain.name:
            raise self.src.error(f"problem is for domain {p.domain_name}, but the domain file "
                                 f"defines {dom.domain.name}", p.domain_name_span)
        objects = dict(dom.constants)
        declared: dict[str, ast.Typed] = {}
        for typed in p.objects:
            if typed.name in declared:
                first = declared[typed.name].span.line
                raise self.src.error(f"duplicate object {typed.name} (first declared on line "
                                     f"{first})", typed.span)
            declared[typed.name] = typed
            dom._declared_types(typed, self.src)
            if typed.name in dom.constants and not dom.hierarchy.fits(
                    typed.types, dom.constants[typed.name]):
                raise self.src.error(f"object {typed.name} is a constant of the domain of "
                                     f"type {_type_text(dom.constants[typed.name])}",
                                     typed.span)
            objects.setdefault(typed.name, typed.types)
        ground = _Scope({}, "the problem")
        for atom in p.init:
            if atom.predicate in dom.derived:
                raise self.src.error(f"derived predicate {atom.predicate} cannot be set in "
                                     ":init", atom.span, 0)
            dom.atom(atom, ground, objects, self.src)
        for value in p.init_values:
            dom.function_term(value.term, ground, objects, self.src)
            if value.value < 0:
                raise self.src.error(f"negative action cost {value.value:g}", value.span, 2)
        dom.formula(p.goal, _Scope({}, "the goal"), objects, self.src)
        if p.metric is not None:
            if p.metric.direction != "minimize":
                raise self.src.error(f"only `(:metric minimize ({COST}))` is supported, not "
                                     f"{p.metric.direction}", p.metric.span, 1,
                                     UnsupportedFeatureError)
            dom.function_term(p.metric.expression, ground, objects, self.src)


def _type_text(types: tuple[str, ...]) -> str:
    return types[0] if len(types) == 1 else f"(either {' '.join(types)})"
