"""PATH... -> Jobs: every problem file under the paths, each with its domain.

A problem file is a `*.pddl` that is not a domain file (folders are searched
recursively). Its domain is found the ways IPC benchmark sets lay them out,
most specific first:

    pNN-domain.pddl, pNN_domain.pddl, domain_pNN.pddl, domain-pNN.pddl
        beside the problem, where pNN is the problem's stem or a prefix of it
        cut at `-` or `_` (psr-small: p01-s2-n1-l2-f50.pddl -> p01-domain.pddl)
    domain.pddl beside the problem, then in its parent folder
    ../../domains/<folder>/domain.pddl (this repository: problems/X/pNN.pddl)

A problem whose domain cannot be found is still a Job (with `domain=None`),
so that the batch records it as an `error` line instead of stopping.

Paths in a Job are absolute: a results line must name its problem whatever
folder the batch ran in, and a Dask worker does not share the batch's cwd.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path

from tampcli.errors import UsageError

_DOMAIN_NAME = re.compile(r"(^|[-_])domain([-_]|$)", re.IGNORECASE)
_DEFINE = re.compile(r"\(\s*define\s*\(\s*(domain|problem)\b", re.IGNORECASE)
_COMMENT = re.compile(r";[^\n]*")
_SNIFF_BYTES = 8192


@dataclass(frozen=True)
class Job:
    """One problem to run, by absolute paths; `domain` is None when no domain
    file was found."""

    problem: str
    domain: str | None
    label: str  # the domain's folder name: rows of the summary are grouped by it


def discover(paths: list[str]) -> list[Job]:
    """All problems under `paths` in natural order, without duplicates."""
    problems: list[Path] = []
    for given in paths:
        path = Path(given)
        if path.is_dir():
            found = sorted(_pddl_files(path), key=natural_key)
            problems.extend(p for p in found if not is_domain_file(p))
        elif path.is_file():
            if not os.access(path, os.R_OK):
                raise UsageError("cannot read file: permission denied", path=given)
            if not is_domain_file(path):
                problems.append(path)
        elif path.exists():
            raise UsageError("not a file or folder", path=given)
        else:
            raise UsageError("no such file or folder", path=given)
    seen: set[str] = set()
    jobs = []
    for problem in problems:
        absolute = os.path.abspath(problem)
        if absolute in seen:
            continue
        seen.add(absolute)
        domain = find_domain(problem)
        domain_path = None if domain is None else os.path.abspath(domain)
        jobs.append(Job(absolute, domain_path, domain_label(domain_path, absolute)))
    if not jobs:
        raise UsageError("no problem files found (a problem is a *.pddl file that is not a "
                         "domain file)", path=" ".join(paths) or None)
    return jobs


def _pddl_files(folder: Path) -> list[Path]:
    """*.pddl under `folder`, skipping hidden folders (.git, .venv: a virtualenv
    may hold the PDDL test files of installed planners)."""

    def unreadable(err: OSError):
        raise UsageError(f"cannot read folder: {err.strerror}", path=err.filename)

    found = []
    for root, dirs, files in os.walk(folder, onerror=unreadable):
        dirs[:] = [d for d in dirs if not d.startswith(".")]
        found.extend(Path(root) / f for f in files if f.lower().endswith(".pddl"))
    return [p for p in found if p.is_file()]


def largest_first(jobs: list[Job]) -> list[Job]:
    """Jobs in decreasing problem-file size: bigger problems tend to run longer,
    and starting the long ones first keeps every job slot busy to the end
    instead of leaving one slot idle while the last long problem runs."""

    def size(job: Job) -> int:
        try:
            return os.path.getsize(job.problem)
        except OSError:
            return 0

    return sorted(jobs, key=size, reverse=True)


def domain_label(domain: str | None, problem: str) -> str:
    """The name a summary row goes by: the domain file's folder (else the problem's)."""
    return Path(domain or problem).resolve().parent.name


def find_domain(problem: Path) -> Path | None:
    for candidate in domain_candidates(problem):
        if candidate.is_file():
            return candidate
    return None


def domain_candidates(problem: Path) -> list[Path]:
    """Where the domain of `problem` may be, most specific first."""
    folder = problem.parent
    candidates = []
    for stem in _stem_prefixes(problem.stem):
        for pattern in ("{}-domain", "{}_domain", "domain_{}", "domain-{}"):
            candidates.append(folder / (pattern.format(stem) + ".pddl"))
    candidates.append(folder / "domain.pddl")
    candidates.append(folder.parent / "domain.pddl")
    resolved = folder.resolve()
    candidates.append(resolved.parent.parent / "domains" / resolved.name / "domain.pddl")
    return candidates


def _stem_prefixes(stem: str) -> list[str]:
    """'p01-s2-n1' -> ['p01-s2-n1', 'p01-s2', 'p01']."""
    cuts = [m.start() for m in re.finditer(r"[-_]", stem)]
    return [stem] + [stem[:i] for i in reversed(cuts) if i > 0]


def is_domain_file(path: Path) -> bool:
    """By its `(define (domain ...` when readable, else by its name."""
    try:
        with open(path, "rb") as f:
            head = f.read(_SNIFF_BYTES).decode("utf-8", errors="replace")
    except OSError:
        head = ""
    match = _DEFINE.search(_COMMENT.sub("", head))
    if match:
        return match.group(1).lower() == "domain"
    return bool(_DOMAIN_NAME.search(path.stem))


def natural_key(path: Path) -> tuple:
    """Order 'p2' before 'p10' (and probBLOCKS-4-0 before probBLOCKS-10-0)."""
    parts = re.split(r"(\d+)", str(path))
    return tuple((0, int(p), "") if p.isdigit() else (1, 0, p) for p in parts)
