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

from lark import Lark, Token
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken

from tampcli.errors import InputError, PDDLSyntaxError, UnsupportedFeatureError, source_line_at
from tampcli.pddl import ast
from tampcli.pddl.builder import Builder, LocatedError
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
                transformer=Builder(), cache=cache)


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
    except LocatedError as err:
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
        # At the end of the last line, not on the empty one after a final newline.
        lines = text.removesuffix("\n").split("\n")
        line, column = len(lines), len(lines[-1].removesuffix("\r")) + 1
        expected = getattr(err, "expected", None) or getattr(err, "accepts", None) or ()
        return PDDLSyntaxError(
            "unexpected end of file (unbalanced parentheses?)", path, line, column,
            source_line_at(text, line), tuple(sorted({_describe_terminal(t) for t in expected})))
    if isinstance(err, UnexpectedToken):
        try:
            expected = err.accepts or err.expected
        except LocatedError:  # trying the alternatives ran into a refused feature
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


# Constructs outside the accepted fragment that the grammar has no place
# for: each is recognised by how it opens. A number after `(at` can only be a
# timed initial literal: names start with a letter.
_REFUSED = (
    (r":durative-action(?![\w-])", "durative actions", ":durative-actions"),
    (r":constraints(?![\w-])", "constraints", ":constraints"),
    (r"preference(?![\w-])", "preferences", ":preferences"),
    (r"at\s+[-+]?\.?[0-9]", "timed initial literals", ":timed-initial-literals"),
)
_REFUSED_RE = re.compile(r"\(\s*(?:" + "|".join(f"({pattern})" for pattern, _, _ in _REFUSED)
                         + r")|;[^\n]*", re.IGNORECASE)


def _check_refused(text: str, path: str | None) -> None:
    """Refuse features outside the accepted fragment by name, before parsing."""
    for match in _REFUSED_RE.finditer(text):
        if match.lastindex is None:  # a comment
            continue
        _, feature, requirement = _REFUSED[match.lastindex - 1]
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


def _with_path(node, path):
    return node if path is None else dataclasses.replace(node, path=path)
