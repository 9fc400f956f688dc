"""Shared test scenes: the real loaders, a World per scene, skeletons from plan text."""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass
from pathlib import Path

if sys.version_info >= (3, 11):
    import tomllib
else:
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[2]
SCENES = Path(__file__).resolve().parent / "scenes"


@dataclass(frozen=True)
class Op:
    """A ground action as the search produces it (name, schema, arguments)."""

    name: str
    action: str
    args: tuple[str, ...]


def ops(*texts: str) -> list[Op]:
    out = []
    for t in texts:
        parts = t.strip("()").split()
        out.append(Op(t, parts[0], tuple(parts[1:])))
    return out


@dataclass(frozen=True)
class _Mode:
    action: str
    kind: str
    object: str | None = None
    on: str | None = None
    to: str | None = None
    params: tuple[str, ...] = ()


def load_modes(domain_dir: str):
    """The geometry package's loader when present; else the file read as SPEC.md says."""
    path = ROOT / "domains" / domain_dir / "modes.toml"
    try:
        from tampcli.geometry.scene import load_modes as real
        from tampcli.pddl import parser

        return real(path, parser.parse_domain_file(ROOT / "domains" / domain_dir /
                                                   "domain.pddl"))
    except ImportError:
        pass
    text = (ROOT / "domains" / domain_dir / "domain.pddl").read_text()
    params = {m.group(1).lower(): tuple(re.findall(r"\?[\w-]+", m.group(2)))
              for m in re.finditer(r":action\s+(\S+)\s+:parameters\s*\(([^)]*)\)", text)}
    data = tomllib.loads(path.read_text())
    return {k: _Mode(k, v["mode"], v.get("object"), v.get("on"), v.get("to"), params[k])
            for k, v in data.items()}


def load_scene(name: str):
    from tampcli.geometry.scene import load_scene as real

    return real(SCENES / f"{name}.scene.toml", geometric=False)
