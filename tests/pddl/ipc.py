"""The IPC benchmark files: problems in natural order and the domain file of each."""

import re
from pathlib import Path

from tests.conftest import IPC


def natural_key(path: Path) -> list:
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", path.name)]


def is_domain_file(path: Path) -> bool:
    return "domain" in path.name


def domains() -> list[Path]:
    return sorted(p for p in IPC.iterdir() if p.is_dir())


def problems(folder: Path) -> list[Path]:
    return sorted((p for p in folder.glob("*.pddl") if not is_domain_file(p)), key=natural_key)


def domain_of(problem: Path) -> Path:
    """`domain.pddl`, or the per-problem `pNN-domain.pddl`, `domain_pNN.pddl`, `domain-pNN.pddl`."""
    folder, stem = problem.parent, problem.stem
    number = re.match(r"p\d+", stem)
    keys = [stem] + ([number.group()] if number else [])
    for key in keys:
        for name in (f"{key}-domain.pddl", f"domain_{key}.pddl", f"domain-{key}.pddl"):
            if (folder / name).is_file():
                return folder / name
    return folder / "domain.pddl"


def pairs(first: int | None = None) -> list[tuple[Path, Path]]:
    """(domain, problem) for the `first` problems of every domain (all when None)."""
    return [(domain_of(p), p) for d in domains() for p in problems(d)[:first]]
