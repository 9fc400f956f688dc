"""PDDL text -> AST, with our own LALR grammar (grammar.lark).

The parser is built once per process and applies the tree builder inline
while parsing (no intermediate parse tree, no recursion), so deep or large
inputs cost time linear in their size and never a RecursionError. Every
failure is an InputError that points at the offending place.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import os
import re
import sys
from pathlib import Path

from lark import Lark, Token, Transformer
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken

from tampcli.errors import InputError, PDDLSyntaxError, UnsupportedFeatureError, source_line_at
from tampcli.pddl import ast
from tampcli.pddl.lexer import PDDLLexer

# Real PDDL nests a few dozen levels; the semantic passes recurse over
# formulas, so deeper input is refused up front rather than crashing later.
MAX_NESTING = 256

_TOKEN_NAMES = {
    "LPAR": '"("',
    "RPAR": '")"',
    "NAME": "a name",
    "VARIABLE": "a variable (?x)",
    "NUMBER": "a number",
    "REQUIRE_KEY": "a requirement such as :strips",
    "EQUALS": '"="',
    "MINUS": '"-"',
    "BINARY_COMP": "a comparison",
    "BINARY_OP": "an arithmetic operator",
    "ATOM": '"("',
    "GROUND_ATOM": '"("',
    "$END": "end of file",
}


@functools.lru_cache(maxsize=1)
def _lark() -> Lark:
    return build_lark(_cache_file())


def build_lark(cache: str | bool = False) -> Lark:
    """The parser; with `cache`, lark's tables are kept in that file (10x faster to load)."""
    grammar = (Path(__file__).with_name("grammar.lark")).read_text()
    return Lark(grammar, parser="lalr", lexer=PDDLLexer, maybe_placeholders=False,
                transformer=_Builder(), cache=cache)


def _cache_file() -> str | bool:
    """A file in the user's own cache folder, named after the grammar.

    Not lark's default (a shared temporary folder): the cache is a pickle,
    which nobody else should be able to write. Lark checks the grammar's
    hash when loading and rebuilds on any mismatch or unreadable file.
    """
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    grammar = (Path(__file__).with_name("grammar.lark")).read_bytes()
    digest = hashlib.sha256(grammar).hexdigest()[:16]
    folder = Path(base) / "tampcli"
    try:
        folder.mkdir(parents=True, exist_ok=True, mode=0o700)
    except OSError:
        return False
    if not os.access(folder, os.W_OK):
        return False
    return str(folder / f"grammar-{digest}-py{sys.version_info[0]}{sys.version_info[1]}.lark")


def parse_domain(text: str, path: str | None = None) -> ast.Domain:
    result = parse(text, path)
    if not isinstance(result, ast.Domain):
        raise InputError("expected a domain definition `(define (domain NAME) ...)`, "
                         "found a problem", path, result.span.line or 1, result.span.column or 1,
                         source_line_at(text, result.span.line or 1))
    return result


def parse_problem(text: str, path: str | None = None) -> ast.Problem:
    result = parse(text, path)
    if not isinstance(result, ast.Problem):
        raise InputError("expected a problem definition `(define (problem NAME) ...)`, "
                         "found a domain", path, result.span.line or 1, result.span.column or 1,
                         source_line_at(text, result.span.line or 1))
    return result


def parse(text: str, path: str | None = None) -> ast.Domain | ast.Problem:
    """Parse a domain or a problem; raise InputError with its location."""
    _check_nesting(text, path)
    _check_refused(text, path)
    try:
        node = _lark().parse(text)
    except _LocatedError as err:
        raise err.to_input_error(text, path) from None
    except UnexpectedInput as err:
        raise _syntax_error(err, text, path) from None
    return _with_path(node, path)


def read_file(path: str | Path) -> str:
    try:
        data = Path(path).read_bytes()
    except FileNotFoundError:
        raise InputError("file not found", str(path)) from None
    except IsADirectoryError:
        raise InputError("is a directory, expected a PDDL file", str(path)) from None
    except OSError as err:
        raise InputError(f"cannot read: {err.strerror}", str(path)) from None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as err:
        line = data[: err.start].count(b"\n") + 1
        return_col = err.start - (data.rfind(b"\n", 0, err.start) + 1) + 1
        shown = source_line_at(data.decode("utf-8", "replace"), line)
        raise InputError("not UTF-8 text", str(path), line, return_col, shown) from None


def parse_domain_file(path: str | Path) -> ast.Domain:
    return parse_domain(read_file(path), str(path))


def parse_problem_file(path: str | Path) -> ast.Problem:
    return parse_problem(read_file(path), str(path))


# ---------------------------------------------------------------- errors


class _LocatedError(Exception):
    """Raised inside the tree builder, turned into an InputError by parse()."""

    def __init__(self, cls: type[InputError], message: str, line: int, column: int):
        super().__init__(message)
        self.cls, self.message, self.line, self.column = cls, message, line, column

    def to_input_error(self, text: str, path: str | None) -> InputError:
        return self.cls(self.message, path, self.line, self.column, source_line_at(text, self.line))


def _describe_terminal(name: str) -> str:
    if name in _TOKEN_NAMES:
        return _TOKEN_NAMES[name]
    try:
        pattern = _lark().get_terminal(name).pattern
    except KeyError:
        return name
    return f'"{pattern.value}"' if pattern.type == "str" else name.lower()


def _describe_found(err: UnexpectedInput, text: str) -> str:
    if isinstance(err, UnexpectedToken):
        if err.token.type == "$END":
            return "end of file"
        token = err.token
        if token.start_pos is not None and token.end_pos is not None:
            return f'"{text[token.start_pos:token.end_pos]}"'  # as written, not lower-cased
        return f'"{token}"'
    if isinstance(err, UnexpectedCharacters):
        return f'"{text[err.pos_in_stream]}"'
    return "end of file"


def _syntax_error(err: UnexpectedInput, text: str, path: str | None) -> InputError:
    if isinstance(err, UnexpectedEOF) or (
        isinstance(err, UnexpectedToken) and err.token.type == "$END"
    ):
        lines = text.splitlines() or [""]
        line, column = len(lines), len(lines[-1]) + 1
        expected = getattr(err, "expected", None) or getattr(err, "accepts", None) or ()
        return PDDLSyntaxError(
            "unexpected end of file (unbalanced parentheses?)", path, line, column,
            source_line_at(text, line), tuple(sorted({_describe_terminal(t) for t in expected})))
    if isinstance(err, UnexpectedToken):
        try:
            expected = err.accepts or err.expected
        except _LocatedError:  # trying the alternatives ran into a refused feature
            expected = err.expected
    else:
        expected = err.allowed or ()
    found = _describe_found(err, text)
    described = tuple(sorted({_describe_terminal(t) for t in expected}))
    message = f"unexpected {found}"
    if set(expected) == {"$END"}:
        message += ' after the end of the definition (a ")" too many before it?)'
    misplaced = _misplaced_keyword(err)
    if misplaced:
        line, column, word = misplaced
        return PDDLSyntaxError(f"`{word}` is not allowed here", path, line, column,
                               source_line_at(text, line))
    return PDDLSyntaxError(message, path, err.line, err.column,
                           source_line_at(text, err.line), described)


# Words that open a formula or an effect; where the grammar has no place for
# them the lexer reads them as names, and the error comes a token later.
_CONNECTIVES = frozenset({"and", "or", "not", "imply", "exists", "forall", "when", "either",
                          "increase", "decrease", "assign", "scale-up", "scale-down"})


def _misplaced_keyword(err: UnexpectedInput) -> tuple[int, int, str] | None:
    """`(or` in an effect, `(when` in a condition...: where the keyword is."""
    stack = getattr(getattr(err, "state", None), "value_stack", None) or ()
    if len(stack) < 2:
        return None
    lpar, word = stack[-2], stack[-1]
    if (isinstance(lpar, Token) and lpar.type == "LPAR" and isinstance(word, Token)
            and word.type == "NAME" and word.value in _CONNECTIVES):
        return word.line, word.column, word.value
    return None


_REFUSED = {
    ":durative-action": ("durative actions", ":durative-actions"),
    ":constraints": ("constraints", ":constraints"),
    "preference": ("preferences", ":preferences"),
    ":timed-initial-literals": ("timed initial literals", ":timed-initial-literals"),
}
_REFUSED_RE = re.compile(r"\(\s*(" + "|".join(map(re.escape, _REFUSED)) + r")(?![\w-])|;[^\n]*",
                         re.IGNORECASE)


def _check_refused(text: str, path: str | None) -> None:
    """Refuse features outside the accepted fragment by name, before parsing."""
    for match in _REFUSED_RE.finditer(text):
        if match.group(1) is None:  # a comment
            continue
        feature, requirement = _REFUSED[match.group(1).lower()]
        line = text.count("\n", 0, match.start()) + 1
        column = match.start() - (text.rfind("\n", 0, match.start()) + 1) + 1
        raise UnsupportedFeatureError(f"{feature} are not supported (requirement {requirement})",
                                      path, line, column, source_line_at(text, line))


_PAREN_RUNS = re.compile(r"\(+|\)+|;[^\n]*")


def _check_nesting(text: str, path: str | None) -> None:
    """Refuse nesting deeper than MAX_NESTING, pointing at the first "(" too deep.

    Runs of parentheses are taken whole, so a megabyte of "(((" is a handful
    of matches.
    """
    depth = 0
    for match in _PAREN_RUNS.finditer(text):
        run = match.group()
        if run[0] == "(":
            depth += len(run)
            if depth > MAX_NESTING:
                pos = match.end() - (depth - MAX_NESTING)
                line = text.count("\n", 0, pos) + 1
                column = pos - (text.rfind("\n", 0, pos) + 1) + 1
                raise PDDLSyntaxError(f"nesting deeper than {MAX_NESTING} levels",
                                      path, line, column, source_line_at(text, line))
        elif run[0] == ")":
            depth -= len(run)


# ---------------------------------------------------------------- tree builder
#
# The grammar keeps the outer parentheses of each rule as LPAR/RPAR tokens so
# that the inline builder (which gets no lark `meta`) can still give every
# node its source span; `_paren` strips them off again.


def _tok_span(tok: Token) -> ast.Span:
    return ast.Span(tok.line, tok.column, tok.end_line or tok.line, tok.end_column or tok.column)


def _paren(method):
    @functools.wraps(method)
    def wrapper(self, children):
        lp, rp = children[0], children[-1]
        span = ast.Span(lp.line, lp.column, rp.end_line, rp.end_column)
        return method(self, span, children[1:-1])

    return wrapper


def _unsupported(feature: str, requirement: str, where) -> _LocatedError:
    return _LocatedError(UnsupportedFeatureError,
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
                raise _LocatedError(PDDLSyntaxError, f"a type with no {what} before it",
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
            raise _LocatedError(PDDLSyntaxError, f"a second :{kind} section",
                                span.line, span.column)
        fields.setdefault(kind, []).extend(value if kind not in repeatable else [value])
    return fields


class _Builder(Transformer):
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
        return _Section(("requirements", tuple(str(t).lower() for t in children), span))

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
                    raise _LocatedError(UnsupportedFeatureError,
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
        return ast.Domain(
            str(name), tuple(f.get("requirements", ())), tuple(f.get("types", ())),
            tuple(f.get("constants", ())), tuple(f.get("predicates", ())),
            tuple(f.get("functions", ())), tuple(f.get("actions", ())),
            tuple(f.get("axioms", ())), span=span)

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
            raise _LocatedError(UnsupportedFeatureError,
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
            raise _LocatedError(UnsupportedFeatureError,
                                "only `(:metric minimize (total-cost))` is supported "
                                "(requirement :numeric-fluents)", span.line, span.column)
        return _Section(("metric", [ast.Metric(direction, expression, span)], span))

    @_paren
    def problem(self, span, children):
        _define, name, domain_name, *sections = children
        f = _sections(sections)
        init = f.get("init", ())
        return ast.Problem(
            str(name), str(domain_name), tuple(f.get("requirements", ())),
            tuple(f.get("objects", ())),
            tuple(x for x in init if isinstance(x, ast.Atom)),
            tuple(x for x in init if isinstance(x, ast.FunctionValue)),
            f["goal"][0] if "goal" in f else ast.TRUE,
            f["metric"][0] if "metric" in f else None,
            span=span, domain_name_span=_tok_span(domain_name))

    def start(self, children):
        return children[0]


def _with_path(node, path):
    return node if path is None else dataclasses.replace(node, path=path)
