"""Where a problem's geometry lives, by convention (docs/formats.md: files are found beside the
PDDL). Path checks only: a symbolic solve asks this without loading numpy."""

from __future__ import annotations

from pathlib import Path


def find_scene(problem_path: str | Path) -> Path | None:
    """`p01.pddl` -> `p01.scene.toml` beside it, or None when there is none."""
    p = Path(problem_path)
    candidate = p.with_name(p.stem + ".scene.toml")
    return candidate if candidate.is_file() else None


def find_modes(domain_path: str | Path) -> Path | None:
    """`modes.toml` beside the domain file, or None."""
    candidate = Path(domain_path).with_name("modes.toml")
    return candidate if candidate.is_file() else None
