"""The NLPs' variables: named blocks of x, and the one place their names are spelled.

A block is a slice of x: keyframe k's configuration, the continuous grip
parameter of a step, the final placement of a step, an interior waypoint of a
motion. Constraint rows know their Jacobian per block name, so the names are
the NLPs' own vocabulary; what crosses into other modules is typed
(values.Keyframes, values.Placements).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def keyframe_block(k: int) -> str:
    return f"k{k}"


def grip_block(step: int) -> str:
    return f"g{step}"


def placement_block(step: int) -> str:
    return f"p{step}"


def waypoint_block(i: int) -> str:
    return f"w{i}"


@dataclass(frozen=True)
class Layout:
    """Where each block of variables sits in the NLP's x (pack/unpack)."""

    blocks: tuple[tuple[str, int], ...]  # (name, size) in order

    @property
    def size(self) -> int:
        return sum(s for _, s in self.blocks)

    def slices(self) -> dict[str, slice]:
        out, at = {}, 0
        for name, size in self.blocks:
            out[name] = slice(at, at + size)
            at += size
        return out

    def pack(self, values: dict[str, np.ndarray]) -> np.ndarray:
        return np.concatenate([np.asarray(values[name], dtype=float).reshape(size)
                               for name, size in self.blocks]) if self.blocks else np.zeros(0)

    def unpack(self, x: np.ndarray) -> dict[str, np.ndarray]:
        x = np.asarray(x, dtype=float)
        if x.shape != (self.size,):
            raise ValueError(f"expected {self.size} values, got shape {x.shape}")
        return {name: x[s] for name, s in self.slices().items()}
