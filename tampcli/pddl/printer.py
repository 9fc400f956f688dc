"""AST -> PDDL text. Parsing the text again gives an equal tree (spans aside).

The tree is first turned into nested lists of strings (an s-expression),
then laid out: a list that fits in the width stays on one line, a longer
one puts each element on a line of its own under its head.
"""

from __future__ import annotations

from decimal import Decimal

from tampcli.pddl import ast
from tampcli.pddl.types import OBJECT

WIDTH = 90

# A word, a parenthesized list, or a tuple: words kept on one line without
# parentheses (one group of a typed list, `(f ?x) - number`).
Sexp = str | list | tuple


def to_pddl(node: ast.Domain | ast.Problem) -> str:
    if isinstance(node, ast.Domain):
        return print_domain(node)
    if isinstance(node, ast.Problem):
        return print_problem(node)
    raise TypeError(f"not a domain or problem: {type(node).__name__}")


def print_domain(domain: ast.Domain) -> str:
    items: list[Sexp] = ["define", ["domain", domain.name]]
    if domain.requirements:
        items.append([":requirements", *domain.requirements])
    if domain.types:
        items.append([":types", *_typed_list(domain.types)])
    if domain.constants:
        items.append([":constants", *_typed_list(domain.constants)])
    if domain.predicates:
        items.append([":predicates", *([p.name, *_typed_list(p.params)] for p in domain.predicates)])
    if domain.functions:
        functions: list[Sexp] = []
        for f in domain.functions:
            functions.append(([f.name, *_typed_list(f.params)], "-", f.type))
        items.append([":functions", *functions])
    for action in domain.actions:
        items.append([":action", action.name,
                      ":parameters", _typed_list(action.params),
                      ":precondition", _formula(action.precondition),
                      ":effect", _effect(action.effect)])
    for axiom in domain.axioms:
        items.append([":derived", [axiom.name, *_typed_list(axiom.params)], _formula(axiom.body)])
    return _layout(items, 0) + "\n"


def print_problem(problem: ast.Problem) -> str:
    items: list[Sexp] = ["define", ["problem", problem.name], [":domain", problem.domain_name]]
    if problem.requirements:
        items.append([":requirements", *problem.requirements])
    if problem.objects:
        items.append([":objects", *_typed_list(problem.objects)])
    init: list[Sexp] = [_atom(a) for a in problem.init]
    init += (["=", _term(v.term), _number(v.value)] for v in problem.init_values)
    items.append([":init", *init])
    items.append([":goal", _formula(problem.goal)])
    if problem.metric is not None:
        items.append([":metric", problem.metric.direction, _term(problem.metric.expression)])
    return _layout(items, 0) + "\n"


# ---------------------------------------------------------------- to s-expressions


def _typed_list(typed: tuple[ast.Typed, ...]) -> list[Sexp]:
    """`a b - t c - u`, one tuple per group; a trailing run of untyped names
    goes without `- object`."""
    out: list[Sexp] = []
    group: list[Sexp] = []
    for i, item in enumerate(typed):
        group.append(item.name)
        last = i + 1 == len(typed)
        if last or typed[i + 1].types != item.types:
            if not (last and item.types == (OBJECT,)):
                group += ["-", _types(item.types)]
            out.append(tuple(group))
            group = []
    return out


def _types(types: tuple[str, ...]) -> Sexp:
    return types[0] if len(types) == 1 else ["either", *types]


def _atom(atom: ast.Atom) -> Sexp:
    return [atom.predicate, *atom.args]


def _formula(f: ast.Formula) -> Sexp:
    if isinstance(f, ast.Atom):
        return _atom(f)
    if isinstance(f, ast.Not):
        return ["not", _formula(f.part)]
    if isinstance(f, ast.And):
        return ["and", *map(_formula, f.parts)]
    if isinstance(f, ast.Or):
        return ["or", *map(_formula, f.parts)]
    if isinstance(f, ast.Imply):
        return ["imply", _formula(f.antecedent), _formula(f.consequent)]
    if isinstance(f, ast.Exists):
        return ["exists", _typed_list(f.params), _formula(f.body)]
    if isinstance(f, ast.Forall):
        return ["forall", _typed_list(f.params), _formula(f.body)]
    raise TypeError(f"not a formula: {type(f).__name__}")


def _effect(e: ast.Effect) -> Sexp:
    if isinstance(e, ast.Literal):
        return ["not", _atom(e.atom)] if e.negated else _atom(e.atom)
    if isinstance(e, ast.AndEffect):
        return ["and", *map(_effect, e.parts)]
    if isinstance(e, ast.ForallEffect):
        return ["forall", _typed_list(e.params), _effect(e.body)]
    if isinstance(e, ast.WhenEffect):
        return ["when", _formula(e.condition), _effect(e.body)]
    if isinstance(e, ast.Increase):
        amount = e.amount if isinstance(e.amount, ast.FunctionTerm) else _number(e.amount)
        return ["increase", _term(e.function),
                _term(amount) if isinstance(amount, ast.FunctionTerm) else amount]
    raise TypeError(f"not an effect: {type(e).__name__}")


def _term(term: ast.FunctionTerm) -> Sexp:
    return [term.name, *term.args]


def _number(value: float) -> str:
    """Plain decimal digits (the grammar has no exponents), exact for the float."""
    if value == int(value):
        return str(int(value))
    return format(Decimal(repr(value)), "f")


# ---------------------------------------------------------------- layout


def _flat(sexp: Sexp) -> str:
    if isinstance(sexp, str):
        return sexp
    if isinstance(sexp, tuple):
        return " ".join(_flat(x) for x in sexp)
    return "(" + " ".join(_flat(x) for x in sexp) + ")"


def _layout(sexp: Sexp, indent: int) -> str:
    flat = _flat(sexp)
    if isinstance(sexp, tuple) and indent + len(flat) > WIDTH:
        return _fill([_flat(x) for x in sexp], indent)
    if not isinstance(sexp, list) or indent + len(flat) <= WIDTH or len(sexp) < 2:
        return flat
    pad = " " * (indent + 2)
    head, *rest = sexp
    if not isinstance(head, str):
        rest, head = sexp, ""
    lines = ["(" + _flat(head)]
    if rest and (isinstance(rest[0], str) or head in ("define", "forall", "exists")):
        lines[0] += " " + _layout(rest.pop(0), indent + len(lines[0]) + 1)
    i = 0
    while i < len(rest):
        item = rest[i]
        # Keep an action's `:keyword value` pairs on one line where they fit.
        if head == ":action" and i + 1 < len(rest):
            lines.append(pad + item + " " + _layout(rest[i + 1], indent + len(item) + 3))
            i += 2
            continue
        lines.append(pad + _layout(item, indent + 2))
        i += 1
    return "\n".join(lines) + ")"


def _fill(words: list[str], indent: int) -> str:
    """Words on as few lines as fit the width, continuation lines at `indent`."""
    lines, line = [], ""
    for word in words:
        if line and indent + len(line) + 1 + len(word) > WIDTH:
            lines.append(line)
            line = word
        else:
            line = f"{line} {word}" if line else word
    lines.append(line)
    return ("\n" + " " * indent).join(lines)
