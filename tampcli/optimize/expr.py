"""Values with Jacobians over named blocks of variables, and the rows of an NLP.

A block is a slice of the NLP's x ("k3": keyframe 3, "g5": grip parameter of
step 5, "p5": final placement of step 5, "w2": interior waypoints of motion
2). A constraint row knows its Jacobian per block; the assembler drops the
blocks a stage keeps fixed, so one formula serves every stage.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from tampcli.optimize.grips import HeldPose

Jac = dict  # block name -> (m, size) array


def add_jac(a: Jac, b: Jac) -> Jac:
    out = dict(a)
    for k, v in b.items():
        out[k] = out[k] + v if k in out else v
    return out


@dataclass(frozen=True)
class PoseX:
    """An upright-or-not object pose as v = [pos, ax, ay, az] (12,) with d v / d blocks."""

    v: np.ndarray
    jac: Jac = field(default_factory=dict)

    @property
    def pos(self) -> np.ndarray:
        return self.v[0:3]

    @property
    def ax(self) -> np.ndarray:
        return self.v[3:6]

    @property
    def ay(self) -> np.ndarray:
        return self.v[6:9]

    @property
    def az(self) -> np.ndarray:
        return self.v[9:12]

    @property
    def yaw(self) -> float:
        return float(np.arctan2(self.v[4], self.v[3]))

    def matrix(self) -> np.ndarray:
        t = np.eye(4)
        t[:3, 0], t[:3, 1], t[:3, 2], t[:3, 3] = self.ax, self.ay, self.az, self.pos
        return t

    def through(self, g: np.ndarray) -> Jac:
        """Jacobian blocks of rows whose gradient w.r.t. v is g (m, 12)."""
        return {k: g @ j for k, j in self.jac.items()}


def constant_pose(x: float, y: float, z: float, yaw: float) -> PoseX:
    c, s = np.cos(yaw), np.sin(yaw)
    return PoseX(np.array([x, y, z, c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0]))


def planar_pose(block: str, x: float, y: float, z: float, yaw: float) -> PoseX:
    """A resting pose whose (x, y, yaw) is the variable block itself."""
    p = constant_pose(x, y, z, yaw)
    j = np.zeros((12, 3))
    j[0, 0] = j[1, 1] = 1.0
    c, s = np.cos(yaw), np.sin(yaw)
    j[3, 2], j[4, 2], j[6, 2], j[7, 2] = -s, c, -c, -s
    return PoseX(p.v, {block: j})


def held_posex(h: HeldPose, q_block: str, t_block: str | None) -> PoseX:
    v = np.concatenate([h.pos, h.axes[:, 0], h.axes[:, 1], h.axes[:, 2]])
    jq = np.vstack([h.dpos_dq, h.daxes_dq[:, 0, :], h.daxes_dq[:, 1, :], h.daxes_dq[:, 2, :]])
    jac = {q_block: jq}
    if t_block is not None:
        jac[t_block] = np.concatenate([h.dpos_dt, h.daxes_dt[:, 0], h.daxes_dt[:, 1],
                                       h.daxes_dt[:, 2]])[:, None]
    return PoseX(v, jac)


@dataclass
class RowSet:
    """Rows of one kind: `eq` (= 0) or `ineq` (>= 0); labels say what each is about."""

    values: list = field(default_factory=list)
    jacs: list = field(default_factory=list)
    labels: list = field(default_factory=list)  # (step name, what, unit scale)
    # Per add: the blocks its rows may depend on at any x (its Jacobian's at this x
    # and those declared), so a sparse solver's pattern holds for the whole solve.
    blocks: list = field(default_factory=list)

    def add(self, values, jac: Jac, label, depends=()) -> None:
        """`depends`: blocks the rows depend on where they are active, beyond those
        `jac` has here (a collision row beyond its activation distance has none)."""
        values = np.atleast_1d(np.asarray(values, dtype=float))
        self.values.append(values)
        self.jacs.append(jac)
        self.blocks.append(frozenset(jac) | frozenset(depends))
        if isinstance(label, list):
            self.labels.extend(label)
        else:
            self.labels.extend([label] * len(values))

    def assemble(self, slices: dict[str, slice], nx: int):
        m = sum(len(v) for v in self.values)
        val = np.concatenate(self.values) if self.values else np.zeros(0)
        jac = np.zeros((m, nx))
        at = 0
        for v, j in zip(self.values, self.jacs, strict=True):
            for block, a in j.items():
                s = slices.get(block)
                if s is not None:
                    jac[at:at + len(v), s] += a
            at += len(v)
        return val, jac


    def pattern(self, slices: dict[str, slice], nx: int) -> np.ndarray:
        """(m, nx) bool: where a row's Jacobian may be non-zero (see `blocks`)."""
        out = np.zeros((sum(len(v) for v in self.values), nx), dtype=bool)
        at = 0
        for v, blocks in zip(self.values, self.blocks, strict=True):
            for block in blocks:
                s = slices.get(block)
                if s is not None:
                    out[at:at + len(v), s] = True
            at += len(v)
        return out


@dataclass(frozen=True)
class Label:
    step: str  # action name or "phase 3"
    what: str  # "footprint outside region goal"
    unit: str = "m"  # how to print the violation: "m" (cm), "rad" (deg), "" (raw)

    def words(self, violation: float) -> str:
        # Below what one decimal shows, the finer unit: a row failed by 0.3 mm read
        # "by 0.0 cm", as if met (blind34 p06).
        if self.unit == "m":
            amount = f"{100 * abs(violation):.1f} cm" if abs(violation) >= 5e-4 \
                else f"{1000 * abs(violation):.2f} mm"
        elif self.unit == "rad":
            deg = np.degrees(abs(violation))
            amount = f"{deg:.1f} deg" if deg >= 0.05 else f"{deg:.3f} deg"
        else:
            amount = f"{abs(violation):.3g}"
        return f"{self.step}: {self.what} by {amount}"
