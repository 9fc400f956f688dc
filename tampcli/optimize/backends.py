"""The solvers of the path stage's NLPs, by the name `solve --nlp` takes.

Each solves the NLP of nlp.py (evaluate(x) -> Rows over a layout, bounds, an
iteration cap, a wall-clock deadline) and returns an NlpOutcome judged the same
way. The final and keyframe stages keep SLSQP: their NLPs are small.

Light to import (options.py checks names against BACKENDS before any scene is
read): the solvers, scipy and cyipopt are imported when a backend solves.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, ClassVar, Protocol

if TYPE_CHECKING:
    from tampcli.optimize.nlp import NlpOutcome

# Path NLPs with at least this many variables go to Ipopt under `auto`; None: none do.
# Measured (bench/results/ipopt.md, docs/ipopt.md), SLSQP's CPU time over Ipopt's on the
# path stage: 1.0 to 1.8 from 133 variables while SLSQP iterated on the NLP's own
# variables; on whitened ones (nlp_space.py) 0.3 to 0.8 at every size, 14 to 273.
IPOPT_FROM: int | None = None
# SLSQP's stopping test on the change of the cost, for the path stage's NLPs: 15 to 22 %
# fewer iterations than at 1e-6 on arm-kitchen, arm-hanoi p01 and arm-pick-place p03,
# p05, objectives within 0.03 % (a motion's cost is 0.01 to 1 rad^2). The final and
# keyframe NLPs keep 1e-6 (`Slsqp()`): a keyframe's cost is the skeleton's bound.
PATH_FTOL = 1e-5


class NlpBackend(Protocol):
    name: ClassVar[str]

    def missing(self) -> str | None:
        """What to install before this backend can solve, or None."""

    def solve(self, evaluate, layout, x0, bounds, max_iterations: int,
              deadline: float) -> NlpOutcome: ...


@dataclass(frozen=True)
class Slsqp:
    """scipy's SLSQP (nlp.solve_nlp): dense, its work grows with the cube of the
    variables."""

    name: ClassVar[str] = "slsqp"
    ftol: float = 1e-6

    def missing(self) -> str | None:
        return None

    def solve(self, evaluate, layout, x0, bounds, max_iterations, deadline) -> NlpOutcome:
        from tampcli.optimize.nlp import solve_nlp

        return solve_nlp(evaluate, layout, x0, bounds, max_iterations, deadline, self.ftol)


@dataclass(frozen=True)
class Ipopt:
    """Ipopt's interior point method through cyipopt (an optional extra)."""

    name: ClassVar[str] = "ipopt"

    def missing(self) -> str | None:
        from tampcli.optimize.ipopt_backend import missing

        return missing()

    def solve(self, evaluate, layout, x0, bounds, max_iterations, deadline) -> NlpOutcome:
        from tampcli.optimize import ipopt_backend

        return ipopt_backend.solve_ipopt(evaluate, layout, x0, bounds, max_iterations,
                                         deadline)


@dataclass(frozen=True)
class Auto:
    """Ipopt for an NLP of at least `ipopt_from` variables (None: none) when cyipopt
    is installed, SLSQP otherwise."""

    name: ClassVar[str] = "auto"
    ipopt_from: int | None = IPOPT_FROM

    def missing(self) -> str | None:
        return None

    def pick(self, size: int) -> NlpBackend:
        if self.ipopt_from is not None and size >= self.ipopt_from \
                and Ipopt().missing() is None:
            return Ipopt()
        return Slsqp(PATH_FTOL)

    def solve(self, evaluate, layout, x0, bounds, max_iterations, deadline) -> NlpOutcome:
        return self.pick(layout.size).solve(evaluate, layout, x0, bounds, max_iterations,
                                            deadline)


BACKENDS: dict[str, NlpBackend] = {b.name: b for b in (Slsqp(PATH_FTOL), Ipopt(), Auto())}
