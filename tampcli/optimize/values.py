"""What the stages hand each other (and a later skeleton, as a warm start): typed values.

The NLPs themselves work on named blocks of x (layout.py); these are the
values read out of a solved NLP and put back into the next one.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from tampcli.optimize.layout import grip_block, keyframe_block, placement_block


@dataclass(frozen=True)
class GripChoice:
    """The discrete part of a step's grip, fixed by the initial guess and then kept
    (the continuous part, a side grasp's pitch, is a variable of the keyframe NLP)."""

    psi: float | None = None  # arm: object yaw minus tool yaw (top); approach direction (side)
    family: str | None = None  # arm: a key of grasp_families.FAMILIES (None: "top")
    roll: float = 1.0  # arm side grasp: -1 turns the hand over about its approach
    z: float | None = None  # planar: height of the object's centre while it is held
    yaw: float | None = None  # planar: the object's yaw while it is held (the disk cannot turn)
    face: float | None = None  # push: the contacted face (push_contact.Face.angle)
    reach: float | None = None  # push (arm): tool origin to the object's centre, measured
    level: bool = False  # push (arm): the hand level, its fingertips against the face
    # push (arm): 0, both open fingers on the face; +1 / -1, only the one on the tool's
    # +y / -y side, centred on the contact (a face narrower than the fingers' spread)
    finger: int = 0
    shift: float | None = None  # push (arm), one finger: its contact along the tool's y, measured
    # push (arm), hand down: the fingers one behind the other along the face's normal,
    # the front one's outer side on the face (a narrow object among neighbours)
    crosswise: bool = False


NO_CHOICE = GripChoice()


@dataclass(frozen=True)
class Placement:
    """Where a place or push leaves its object: (x, y) and yaw; z follows from the stack."""

    x: float
    y: float
    yaw: float

    def array(self) -> np.ndarray:
        return np.array([self.x, self.y, self.yaw])


def placement_blocks(placements: Mapping[int, Placement]) -> dict[str, np.ndarray]:
    """The final NLP's blocks of these placements (see layout.placement_block)."""
    return {placement_block(s): p.array() for s, p in placements.items()}


def placements_from_blocks(blocks: Mapping[str, np.ndarray], steps) -> dict[int, Placement]:
    """The placement of each step in `steps` (indices) from the final NLP's blocks."""
    out = {}
    for s in steps:
        x, y, yaw = (float(v) for v in blocks[placement_block(s)])
        out[s] = Placement(x, y, yaw)
    return out


@dataclass(frozen=True)
class Keyframes:
    """A configuration per keyframe and the continuous grip parameter of each step that has one."""

    q: tuple[np.ndarray, ...] = ()
    grip: Mapping[int, float] = field(default_factory=dict)  # step index -> t

    def __len__(self) -> int:
        return len(self.q)

    def blocks(self) -> dict[str, np.ndarray]:
        """The keyframe NLP's blocks (see layout.keyframe_block, layout.grip_block)."""
        out = {keyframe_block(k): q for k, q in enumerate(self.q)}
        out.update({grip_block(s): np.array([t]) for s, t in self.grip.items()})
        return out

    @classmethod
    def from_blocks(cls, blocks: Mapping[str, np.ndarray], n_keyframes: int,
                    grip_steps) -> Keyframes:
        return cls(tuple(np.array(blocks[keyframe_block(k)], dtype=float)
                         for k in range(n_keyframes)),
                   {s: float(blocks[grip_block(s)][0]) for s in grip_steps})

    def least_costs(self, start, T: int) -> tuple[float, ...]:
        """Per motion, the least path cost through its two keyframes (the first from
        `start`): |q_b - q_a|^2 / T, by Cauchy-Schwarz over its T segments."""
        qs = [np.asarray(start, dtype=float), *self.q]
        return tuple(float(np.sum((b - a) ** 2)) / T for a, b in zip(qs, qs[1:], strict=False))

    def warmed(self, warm: Keyframes) -> Keyframes:
        """These keyframes with those `warm` has for the same keyframes and steps."""
        q = tuple(np.array(warm.q[k], dtype=float)
                  if k < len(warm.q) and np.shape(warm.q[k]) == np.shape(v) else v
                  for k, v in enumerate(self.q))
        return Keyframes(q, {s: float(warm.grip.get(s, t)) for s, t in self.grip.items()})
