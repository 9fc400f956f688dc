"""The KKT certificate of a trajectory NLP's answer, as plain data (no numpy).

optimize/kkt.py computes it at each solved NLP; a stage's result, each
skeleton record and the Solution carry one per stage (`KktStages`), and
solution.json holds them under `kkt` (docs/formats.md, "KKT certificates").
Reading one back is tolerant of its absence: files written before it existed
stay valid.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

from tampcli.errors import SolutionFileError

KINDS = ("eq", "ineq", "bound")


@dataclass(frozen=True)
class ActiveConstraint:
    """Constraint rows of one name, active at the answer, whose multipliers have one sign.

    name: the rows' label, as the worst-row messages spell it
        ("(place a goal): overlaps b"), or "k2 at its lower bound" for a
        variable block at a bound.
    kind: "eq", "ineq" or "bound".
    rows: how many rows the group has.
    multiplier: of those rows' multipliers, the one largest in magnitude (signed).
    """

    name: str
    kind: str
    rows: int
    multiplier: float


@dataclass(frozen=True)
class KktCertificate:
    """How nearly an NLP's answer meets the KKT conditions.

    stationarity: |grad f - J_eq^T lambda - J_act^T mu| with mu >= 0 on the active
        inequalities and bounds (a bounded least-squares fit): ~0 at a KKT point.
    free_stationarity: the same fit with mu free in sign.
    gradient: |grad f|, the scale the two residuals compare to.
    violation: the largest constraint violation (m or rad).
    complementarity: the largest |mu_i g_i| over the active rows.
    min_multiplier: the least inequality or bound multiplier of the reported fit
        (the signed fit when dual feasible, else the free fit); negative when
        dual feasibility fails. None: no inequality or bound active.
    dual_feasible: the signed fit leaves at most about twice the free fit's
        residual (optimize/kkt.py): multipliers of the right sign explain the
        gradient.
    nlps: NLP answers combined (a path stage solves one NLP per motion).
    active: the active constraints by name, largest multiplier first.
    """

    stationarity: float
    free_stationarity: float
    gradient: float
    violation: float
    complementarity: float
    min_multiplier: float | None
    dual_feasible: bool
    nlps: int = 1
    active: tuple[ActiveConstraint, ...] = ()


@dataclass(frozen=True)
class KktStages:
    """One certificate per stage whose NLP was solved; None where none was."""

    final: KktCertificate | None = None
    keyframes: KktCertificate | None = None
    path: KktCertificate | None = None

    def of(self, stage: str | None) -> KktCertificate | None:
        """The certificate of `stage` (None for no stage, or one without)."""
        return dict(self.items()).get(stage)

    def items(self) -> list[tuple[str, KktCertificate]]:
        return [(f.name, getattr(self, f.name)) for f in fields(self)
                if getattr(self, f.name) is not None]


def stages_to_dict(stages: KktStages) -> dict:
    return {stage: certificate_to_dict(c) for stage, c in stages.items()}


def certificate_to_dict(c: KktCertificate) -> dict:
    return {
        "stationarity": _num(c.stationarity),
        "free_stationarity": _num(c.free_stationarity),
        "gradient": _num(c.gradient),
        "violation": _num(c.violation),
        "complementarity": _num(c.complementarity),
        "min_multiplier": _num(c.min_multiplier),
        "dual_feasible": c.dual_feasible,
        "nlps": c.nlps,
        "active": [{"name": a.name, "kind": a.kind, "rows": a.rows,
                    "multiplier": _num(a.multiplier)} for a in c.active],
    }


def _num(value: float | None) -> float | None:
    if value is None or not math.isfinite(value):
        return None
    return float(value)


_NUMBERS = ("stationarity", "free_stationarity", "gradient", "violation", "complementarity")


def stages_from_dict(value, path: str, key: str) -> KktStages:
    """A `kkt` object read back; absent (None) is no certificate at all."""
    if value is None:
        return KktStages()
    if not isinstance(value, dict):
        raise SolutionFileError(f"expected an object of stage -> certificate, found {value!r}",
                                path, key=key)
    names = [f.name for f in fields(KktStages)]
    for stage in value:
        if stage not in names:
            raise SolutionFileError(f"expected a stage ({', '.join(names)}), found {stage!r}",
                                    path, key=key)
    return KktStages(**{stage: _certificate(c, path, f"{key}.{stage}")
                        for stage, c in value.items()})


def _certificate(value, path: str, key: str) -> KktCertificate:
    if not isinstance(value, dict):
        raise SolutionFileError(f"expected an object, found {value!r}", path, key=key)
    for name in _NUMBERS:
        _number(value.get(name), path, f"{key}.{name}")
    least = value.get("min_multiplier")
    _number(least, path, f"{key}.min_multiplier")
    dual = value.get("dual_feasible")
    if not isinstance(dual, bool):
        raise SolutionFileError(f"expected true or false, found {dual!r}", path,
                                key=f"{key}.dual_feasible")
    nlps = value.get("nlps", 1)
    if not isinstance(nlps, int) or isinstance(nlps, bool) or nlps < 1:
        raise SolutionFileError(f"expected a count >= 1, found {nlps!r}", path,
                                key=f"{key}.nlps")
    active = value.get("active", [])
    if not isinstance(active, list):
        raise SolutionFileError(f"expected a list, found {active!r}", path, key=f"{key}.active")
    return KktCertificate(
        *(_float(value[name]) for name in _NUMBERS),
        min_multiplier=None if least is None else float(least), dual_feasible=dual, nlps=nlps,
        active=tuple(_active(a, path, f"{key}.active[{i}]") for i, a in enumerate(active)))


def _active(value, path: str, key: str) -> ActiveConstraint:
    if not isinstance(value, dict) or not isinstance(value.get("name"), str):
        raise SolutionFileError(f"expected an object with a name, found {value!r}", path,
                                key=key)
    if value.get("kind") not in KINDS:
        raise SolutionFileError(f"expected one of {', '.join(KINDS)}, found "
                                f"{value.get('kind')!r}", path, key=f"{key}.kind")
    rows = value.get("rows")
    if not isinstance(rows, int) or isinstance(rows, bool) or rows < 1:
        raise SolutionFileError(f"expected a count >= 1, found {rows!r}", path,
                                key=f"{key}.rows")
    _number(value.get("multiplier"), path, f"{key}.multiplier")
    return ActiveConstraint(value["name"], value["kind"], rows, _float(value.get("multiplier")))


def _number(value, path: str, key: str) -> None:
    """A number, or null (a value that was not finite when written)."""
    if value is not None and (not isinstance(value, (int, float)) or isinstance(value, bool)):
        raise SolutionFileError(f"expected a number or null, found {value!r}", path, key=key)


def _float(value) -> float:
    return math.nan if value is None else float(value)
