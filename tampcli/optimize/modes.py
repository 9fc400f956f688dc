"""modes.toml -> Modes: what each action schema does to the world (docs/formats.md, "modes.toml").

Values starting with `?` name parameters of the action; they are checked
against the action's parameter list and kept as names, with their index in
`Mode.params` so that `Mode.bind(args)` gives the objects of a grounded
action. A value without `?` names an object or constant directly.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from tampcli.errors import SceneError, source_line_at
from tampcli.geometry.tomlsrc import read_toml
from tampcli.optimize.grasp_families import FAMILIES
from tampcli.optimize.kinds import KINDS, SYMBOLIC
from tampcli.pddl import ast

_KEYS = ("mode", "object", "on", "to", "grasps")


@dataclass(frozen=True)
class Mode:
    action: str
    kind: str  # a key of optimize.kinds.KINDS
    object: str | None = None  # "?b" or an object name
    on: str | None = None
    to: str | None = None
    params: tuple[str, ...] = ()  # the action's parameter names, in order
    line: int | None = field(default=None, compare=False)
    grasps: tuple[str, ...] | None = None  # grasp families it may use (None: every one)

    @property
    def geometric(self) -> bool:
        """The action moves something (its kind is not symbolic)."""
        return KINDS[self.kind].geometric

    def bind(self, args) -> dict[str, str | None]:
        """{"object": ..., "on": ..., "to": ...} for a grounded action's arguments."""
        values = dict(zip(self.params, args, strict=True))
        return {role: (values[v] if v is not None and v.startswith("?") else v)
                for role, v in (("object", self.object), ("on", self.on), ("to", self.to))}


@dataclass(frozen=True)
class Modes(Mapping):
    """Action name -> Mode; an action without a table is `none` (see `missing`)."""

    path: str | None
    table: tuple[tuple[str, Mode], ...]
    missing: tuple[str, ...] = ()  # actions of the domain with no table

    def __getitem__(self, action: str) -> Mode:
        for name, mode in self.table:
            if name == action:
                return mode
        raise KeyError(action)

    def __iter__(self):
        return (name for name, _ in self.table)

    def __len__(self) -> int:
        return len(self.table)

    def get_mode(self, action: str) -> Mode:
        """The mode of an action, `none` when the file has no table for it."""
        try:
            return self[action]
        except KeyError:
            return Mode(action, SYMBOLIC.name)


def load_modes(path: str | Path, domain: ast.Domain) -> Modes:
    src = read_toml(str(path))
    table = []
    for action_name, data in src.data.items():
        line = src.line(action_name)
        if not isinstance(data, dict):
            line = src.line(None, 0, action_name)
            raise SceneError(f"expected a table [{action_name}], got a value", path=src.path,
                             line=line, key=action_name, source_line=source_line_at(src.text, line))
        action = domain.action(action_name.lower())
        if action is None:
            known = ", ".join(a.name for a in domain.actions) or "none"
            raise src.error(f"no action {action_name!r} in domain {domain.name!r} "
                            f"(actions: {known})", action_name, name=action_name)
        for key in data:
            if key not in _KEYS:
                raise src.error(f"unknown key; expected one of {', '.join(_KEYS)}", action_name,
                                0, key)
        kind = data.get("mode")
        if kind is None:
            raise src.error(f"missing key 'mode' (one of {', '.join(KINDS)})", action_name,
                            name=f"{action_name}.mode")
        if not isinstance(kind, str) or kind not in KINDS:
            raise src.error(f"unknown mode {kind!r}; expected one of {', '.join(KINDS)}",
                            action_name, 0, "mode")
        required, optional = KINDS[kind].required, KINDS[kind].optional
        params = tuple(p.name for p in action.params)
        values = {}
        for role in ("object", "on", "to"):
            value = data.get(role)
            if value is None:
                if role in required:
                    raise src.error(f"mode {kind!r} needs `{role}`", action_name, 0, "mode",
                                    f"{action_name}.{role}")
                continue
            if role not in required and role not in optional:
                raise src.error(f"mode {kind!r} takes no `{role}`", action_name, 0, role)
            if not isinstance(value, str) or not value:
                raise src.error(f"expected a parameter name such as \"?b\", got {value!r}",
                                action_name, 0, role)
            value = value.lower()
            if value.startswith("?") and value not in params:
                have = ", ".join(params) or "no parameters"
                raise src.error(f"action {action.name!r} has no parameter {value} (it has "
                                f"{have})", action_name, 0, role)
            values[role] = value
        grasps = _grasps(src, action_name, kind, data.get("grasps"))
        table.append((action.name, Mode(action.name, kind, params=params, line=line,
                                        grasps=grasps, **values)))
    named = {name for name, _ in table}
    missing = tuple(a.name for a in domain.actions if a.name not in named)
    return Modes(src.path, tuple(table), missing)


def _grasps(src, action_name: str, kind: str, value) -> tuple[str, ...] | None:
    """The `grasps` key: a non-empty list of grasp family names, for a kind that takes it."""
    if value is None:
        return None
    if not getattr(KINDS[kind], "takes_grasps", False):
        raise src.error(f"mode {kind!r} takes no `grasps`", action_name, 0, "grasps")
    known = ", ".join(FAMILIES)
    if not isinstance(value, list) or not value:
        raise src.error(f"expected a list of grasp families such as [\"top\", \"side\"] "
                        f"(of {known}), got {value!r}", action_name, 0, "grasps")
    for name in value:
        if not isinstance(name, str) or name not in FAMILIES:
            raise src.error(f"unknown grasp family {name!r}; expected one of {known}",
                            action_name, 0, "grasps")
    return tuple(dict.fromkeys(value))
