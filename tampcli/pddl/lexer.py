"""The PDDL tokenizer, plugged into lark's LALR parser in place of lark's own lexer.

Two reasons. Lark's lexer spent about 70% of a parse building tokens one
regular expression at a time, where PDDL's tokens fit one compiled
alternation. And lark's LALR loop costs a few microseconds per token, while
most of a PDDL file is plain atoms such as `(at truck1 depot2)`: where the
parser accepts an atom, this lexer hands it over as one ATOM (or, in
`:init`, GROUND_ATOM) token, which cuts the parser's work on problem files
about fivefold. An atom the fast pattern does not match (a comment inside,
a keyword as its head) is tokenized the ordinary way and builds the same tree.

Names, variables and requirement keys are lower-cased here (PDDL is
case-insensitive). Keywords (`and`, `:action`, `either`...) are also valid
names; like lark's contextual lexer, a keyword is kept only where the parser
accepts it and is read as a plain name elsewhere.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from lark import Token
from lark.exceptions import UnexpectedCharacters
from lark.lexer import Lexer
from lark.parsers.lalr_analysis import Shift

_NAME = r"[a-z][a-z0-9_\-]*"
_WS = r"[ \t\f\r\n]"
# Lark's terminal names for the token classes of grammar.lark; keyword
# terminals are looked up by their lower-cased text in the lexer config.
_CLASSES = (
    ("VARIABLE", rf"\?{_NAME}"),
    ("NAME", _NAME),
    ("REQUIRE_KEY", rf":{_NAME}"),
    ("NUMBER", r"-?[0-9]+(?:\.[0-9]+)?"),
    ("BINARY_COMP", r"<=|>=|<|>"),
    ("BINARY_OP", r"[+*/]"),
    ("MINUS", r"-"),
    ("EQUALS", r"="),
    ("LPAR", r"\("),
    ("RPAR", r"\)"),
)
# Whitespace and comments are folded into the match of the token after
# them, which halves the number of matches; group "skip" holds them.
_SCAN = re.compile(
    rf"(?P<skip>(?:{_WS}+|;[^\n]*)*)(?:"
    + "|".join(f"(?P<{name}>{pattern})" for name, pattern in _CLASSES)
    + r"|(?P<BAD>.)|\Z)",
    re.IGNORECASE | re.DOTALL,
)
_ATOM = re.compile(rf"\({_WS}*({_NAME})(?:{_WS}+\??{_NAME})*{_WS}*\)", re.IGNORECASE)
_GROUND_ATOM = re.compile(rf"\({_WS}*({_NAME})(?:{_WS}+{_NAME})*{_WS}*\)", re.IGNORECASE)
_FOLDED = frozenset({"VARIABLE", "NAME", "REQUIRE_KEY"})


class PDDLLexer(Lexer):
    """A lark `Lexer` (future interface: it sees the parser state, for context)."""

    __future_interface__ = True

    def __init__(self, lexer_conf):
        self.keywords = {
            t.pattern.value.lower(): t.name
            for t in lexer_conf.terminals
            if t.pattern.type == "str" and re.fullmatch(rf":?{_NAME}", t.pattern.value)
        }
        self.terminals_by_name = lexer_conf.terminals_by_name

    def lex(self, lexer_state, parser_state) -> Iterator[Token]:
        text = lexer_state.text
        keywords = self.keywords
        states = parser_state.parse_conf.states
        scan = _SCAN.match
        memo: dict = {}
        line, line_start, pos = 1, 0, 0
        while True:
            match = scan(text, pos)
            kind = match.lastgroup
            if kind == "skip":  # only whitespace and comments left
                return
            start = match.start(kind)
            if start != pos:
                skipped = match.group("skip")
                newlines = skipped.count("\n")
                if newlines:
                    line += newlines
                    line_start = pos + skipped.rindex("\n") + 1
            column = start - line_start + 1
            if kind == "LPAR":
                atom = None
                if _shifts(states, parser_state.state_stack, "ATOM", memo):
                    kind, atom = "ATOM", _ATOM.match(text, start)
                elif _shifts(states, parser_state.state_stack, "GROUND_ATOM", memo):
                    kind, atom = "GROUND_ATOM", _GROUND_ATOM.match(text, start)
                if atom is not None and atom.group(1).lower() not in keywords:
                    value = atom.group().lower()
                    pos = atom.end()
                    newlines = value.count("\n")
                    if newlines:
                        end_line = line + newlines
                        end_column = pos - (start + value.rindex("\n") + 1) + 1
                    else:
                        end_line, end_column = line, column + len(value)
                    yield Token(kind, value, start, line, column, end_line, end_column, pos)
                    if newlines:
                        line, line_start = end_line, pos - end_column + 1
                    continue
                kind = "LPAR"
            elif kind == "BAD":
                allowed = {name for name in states[parser_state.position] if name.isupper()}
                raise UnexpectedCharacters(text, start, line, column, allowed=allowed,
                                           state=parser_state,
                                           terminals_by_name=self.terminals_by_name)
            value = match.group(kind)
            pos = match.end()
            if kind in _FOLDED:
                value = value.lower()
                keyword = keywords.get(value)
                if keyword is not None and _shifts(states, parser_state.state_stack, keyword, memo):
                    kind = keyword
            yield Token(kind, value, start, line, column, line, column + len(value), pos)


def _shifts(states, stack: list, terminal: str, memo: dict) -> bool:
    """Whether the parser, in the state `stack`, would eventually shift `terminal`.

    An LALR state's table also lists lookaheads merged in from other contexts
    (they would fail after a few reductions), so the reductions are followed
    on a copy of the stack until a shift or a miss. `memo` (one per parse)
    remembers the answers: files repeat the same few stacks.
    """
    action = states[stack[-1]].get(terminal)
    if action is None:
        return False
    if action[0] is Shift:
        return True
    key = (terminal, *stack)
    known = memo.get(key)
    if known is None:
        known = memo[key] = _follow_reductions(states, list(stack), terminal, action)
    return known


def _follow_reductions(states, stack: list, terminal: str, action) -> bool:
    while action is not None and action[0] is not Shift:
        rule = action[1]
        if rule.expansion:
            del stack[-len(rule.expansion):]
        stack.append(states[stack[-1]][rule.origin.name][1])
        action = states[stack[-1]].get(terminal)
    return action is not None
