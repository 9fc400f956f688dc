"""The tree builder: lark's inline transformer from grammar rules to AST nodes.

It runs while the LALR parser reduces (no intermediate parse tree). The
grammar keeps the outer parentheses of each rule as LPAR/RPAR tokens so that
every node gets its source span from them; `_paren` strips them off again.
Mistakes found here (a refused feature, a type before any name) are raised
as LocatedError and turned into InputErrors by parser.parse.
"""

from __future__ import annotations

import functools

from lark import Token, Transformer

from tampcli.errors import InputError, PDDLSyntaxError, UnsupportedFeatureError, source_line_at
from tampcli.pddl import ast


class LocatedError(Exception):
    """Raised inside the tree builder, turned into an InputError by parse()."""

    def __init__(self, cls: type[InputError], message: str, line: int, column: int):
        super().__init__(message)
        self.cls, self.message, self.line, self.column = cls, message, line, column

    def to_input_error(self, text: str, path: str | None) -> InputError:
        return self.cls(self.message, path, self.line, self.column, source_line_at(text, self.line))



def _tok_span(tok: Token) -> ast.Span:
    return ast.Span(tok.line, tok.column, tok.end_line or tok.line, tok.end_column or tok.column)


def _paren(method):
    @functools.wraps(method)
    def wrapper(self, children):
        lp, rp = children[0], children[-1]
        span = ast.Span(lp.line, lp.column, rp.end_line, rp.end_column)
        return method(self, span, children[1:-1])

    return wrapper


def _unsupported(feature: str, requirement: str, where) -> LocatedError:
    return LocatedError(UnsupportedFeatureError,
                        f"{feature} are not supported (requirement {requirement})",
                        where.line, where.column)


class _TypeSpec(tuple):
    """(types, minus token) for `- t` or `- (either t1 t2)` inside a typed list."""


class _Section(tuple):
    """(keyword, value, span) of a domain or problem section."""


def _typed(items: list, what: str) -> tuple[ast.Typed, ...]:
    result: list[ast.Typed] = []
    pending: list[Token] = []
    for item in items:
        if isinstance(item, _TypeSpec):
            types, minus = item
            if not pending:
                raise LocatedError(PDDLSyntaxError, f"a type with no {what} before it",
                                   minus.line, minus.column)
            result.extend(ast.Typed(str(tok), types, _tok_span(tok)) for tok in pending)
            pending = []
        else:
            pending.append(item)
    result.extend(ast.Typed(str(tok), ("object",), _tok_span(tok)) for tok in pending)
    return tuple(result)


def _as_effect(node) -> ast.Effect:
    if isinstance(node, ast.And) and not node.parts:  # `()` as an effect
        return ast.AndEffect((), node.span)
    return node


def _function_term(head) -> ast.FunctionTerm:
    if isinstance(head, Token):  # `total-cost` written without parentheses
        return ast.FunctionTerm(str(head), (), _tok_span(head))
    return head


def _sections(sections, repeatable=()) -> dict[str, list]:
    fields: dict[str, list] = {}
    for kind, value, span in sections:
        if kind in fields and kind not in repeatable:
            raise LocatedError(PDDLSyntaxError, f"a second :{kind} section",
                               span.line, span.column)
        fields.setdefault(kind, []).extend(value if kind not in repeatable else [value])
    return fields


class Builder(Transformer):
    # ---- tokens and small pieces

    def primitive_type(self, children):
        return str(children[0])

    def type_spec(self, children):
        return _TypeSpec(((children[1],), children[0]))

    def either_spec(self, children):
        return _TypeSpec((tuple(children[1:]), children[0]))

    def typed_list_name(self, children):
        return _typed(children, "names")

    def typed_list_variable(self, children):
        return _typed(children, "variables")

    # ---- domain sections

    @_paren
    def require_def(self, span, children):
        return _Section(("requirements", tuple(children), span))

    @_paren
    def types_def(self, span, children):
        return _Section(("types", children[0], span))

    @_paren
    def constants_def(self, span, children):
        return _Section(("constants", children[0], span))

    @_paren
    def predicates_def(self, span, children):
        return _Section(("predicates", tuple(children), span))

    @_paren
    def functions_def(self, span, children):
        return _Section(("functions", children[0], span))

    @_paren
    def atomic_formula_skeleton(self, span, children):
        return ast.PredicateDef(str(children[0]), children[1], span)

    def function_typed_list(self, children):
        functions: list[ast.FunctionDef] = []
        pending: list[ast.PredicateDef] = []
        for item in children:
            if isinstance(item, _TypeSpec):
                types, minus = item
                if types != ("number",):
                    raise LocatedError(UnsupportedFeatureError,
                                       f"functions of type {' '.join(types)} are not supported "
                                       "(requirement :object-fluents)", minus.line, minus.column)
                pending, done = [], pending
            else:
                pending.append(item)
                continue
            functions.extend(ast.FunctionDef(p.name, p.params, "number", p.span) for p in done)
        functions.extend(ast.FunctionDef(p.name, p.params, "number", p.span) for p in pending)
        return tuple(functions)

    def parameters(self, children):
        return ("parameters", children[1])

    def precondition(self, children):
        return ("precondition", children[0])

    def effect_part(self, children):
        return ("effect", _as_effect(children[0]))

    def action_body(self, children):
        return dict(children)

    @_paren
    def action_def(self, span, children):
        name = str(children[0])
        body = children[1] if len(children) > 1 else {}
        action = ast.Action(name, body.get("parameters", ()), body.get("precondition", ast.TRUE),
                            body.get("effect", ast.AndEffect(())), span)
        return _Section(("actions", action, span))

    @_paren
    def derived_def(self, span, children):
        head, body = children
        return _Section(("axioms", ast.Axiom(head.name, head.params, body, span), span))

    @_paren
    def domain(self, span, children):
        _define, name, *sections = children
        f = _sections(sections, repeatable=("actions", "axioms"))
        keys = f.get("requirements", ())
        return ast.Domain(
            str(name), tuple(str(k) for k in keys), tuple(f.get("types", ())),
            tuple(f.get("constants", ())), tuple(f.get("predicates", ())),
            tuple(f.get("functions", ())), tuple(f.get("actions", ())),
            tuple(f.get("axioms", ())), span=span,
            requirement_spans=tuple(_tok_span(k) for k in keys))

    # ---- goal descriptions

    def ATOM(self, tok):
        predicate, *args = tok.value[1:-1].split()
        return ast.Atom(predicate, tuple(args),
                        ast.Span(tok.line, tok.column, tok.end_line, tok.end_column))

    GROUND_ATOM = ATOM

    def atomic_formula(self, children):
        lp, rp = children[0], children[-1]
        return ast.Atom(children[1].value, tuple([c.value for c in children[2:-1]]),
                        ast.Span(lp.line, lp.column, rp.end_line, rp.end_column))

    @_paren
    def gd_empty(self, span, children):
        return ast.And((), span)

    @_paren
    def gd_and(self, span, children):
        return ast.And(tuple(children), span)

    @_paren
    def gd_or(self, span, children):
        return ast.Or(tuple(children), span)

    @_paren
    def gd_not(self, span, children):
        return ast.Not(children[0], span)

    @_paren
    def gd_imply(self, span, children):
        return ast.Imply(children[0], children[1], span)

    @_paren
    def gd_exists(self, span, children):
        return ast.Exists(children[0], children[1], span)

    @_paren
    def gd_forall(self, span, children):
        return ast.Forall(children[0], children[1], span)

    @_paren
    def gd_equality(self, span, children):
        return ast.Atom("=", (str(children[1]), str(children[2])), span)

    @_paren
    def gd_comparison(self, span, children):
        raise _unsupported("numeric conditions", ":numeric-fluents", span)

    # ---- effects

    @_paren
    def effect_and(self, span, children):
        return ast.AndEffect(tuple(_as_effect(c) for c in children), span)

    @_paren
    def effect_forall(self, span, children):
        return ast.ForallEffect(children[0], _as_effect(children[1]), span)

    @_paren
    def effect_when(self, span, children):
        return ast.WhenEffect(children[0], _as_effect(children[1]), span)

    @_paren
    def effect_not(self, span, children):
        return ast.Literal(children[0], True, span)

    def effect_atom(self, children):
        return ast.Literal(children[0], False, children[0].span)

    def assign_op(self, children):
        return str(children[0]).lower()

    @_paren
    def effect_numeric(self, span, children):
        op, head, amount = children
        if op != "increase":
            raise _unsupported(f"numeric effects ({op})", ":numeric-fluents", span)
        if isinstance(amount, Token):  # a variable
            raise LocatedError(UnsupportedFeatureError,
                               "an increase by a variable is not supported; use a number "
                               "or a function term (requirement :numeric-fluents)",
                               amount.line, amount.column)
        return ast.Increase(_function_term(head), amount, span)

    @_paren
    def f_head_compound(self, span, children):
        return ast.FunctionTerm(str(children[0]), tuple(str(c) for c in children[1:]), span)

    def number(self, children):
        return float(children[0])

    @_paren
    def f_arith(self, span, children):
        raise _unsupported("arithmetic expressions", ":numeric-fluents", span)

    # ---- problem

    @_paren
    def problem_domain(self, span, children):
        return children[0]

    @_paren
    def objects_def(self, span, children):
        return _Section(("objects", children[0], span))

    ground_atom = atomic_formula

    @_paren
    def init_not(self, span, children):
        return None  # closed world: a negative initial literal says nothing

    @_paren
    def init_function(self, span, children):
        _eq, head, value = children
        return ast.FunctionValue(_function_term(head), float(value), span)

    @_paren
    def init_def(self, span, children):
        return _Section(("init", tuple(c for c in children if c is not None), span))

    @_paren
    def goal_def(self, span, children):
        return _Section(("goal", [children[0]], span))

    def optimization(self, children):
        return str(children[0]).lower()

    @_paren
    def metric_def(self, span, children):
        direction, expression = children
        if not isinstance(expression, ast.FunctionTerm):
            raise LocatedError(UnsupportedFeatureError,
                               "only `(:metric minimize (total-cost))` is supported "
                               "(requirement :numeric-fluents)", span.line, span.column)
        return _Section(("metric", [ast.Metric(direction, expression, span)], span))

    @_paren
    def problem(self, span, children):
        _define, name, domain_name, *sections = children
        f = _sections(sections)
        init = f.get("init", ())
        keys = f.get("requirements", ())
        return ast.Problem(
            str(name), str(domain_name), tuple(str(k) for k in keys),
            tuple(f.get("objects", ())),
            tuple(x for x in init if isinstance(x, ast.Atom)),
            tuple(x for x in init if isinstance(x, ast.FunctionValue)),
            f["goal"][0] if "goal" in f else ast.TRUE,
            f["metric"][0] if "metric" in f else None,
            span=span, domain_name_span=_tok_span(domain_name),
            requirement_spans=tuple(_tok_span(k) for k in keys))

    def start(self, children):
        return children[0]
