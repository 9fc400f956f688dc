"""A Scene against its PDDL problem and modes: names, obstacles, missing geometry, and
whether a URDF file is one (checked before PyBullet, which says too little)."""

from __future__ import annotations

import dataclasses
from xml.etree import ElementTree

from tampcli.errors import SceneError, source_line_at
from tampcli.geometry.model import Body, Scene
from tampcli.geometry.tomlsrc import TomlSource, read_toml
from tampcli.pddl import ast


def pddl_objects(domain: ast.Domain | None, problem: ast.Problem) -> dict[str, tuple[str, ...]]:
    """Object and constant names -> their types."""
    names = {o.name: o.types for o in problem.objects}
    if domain is not None:
        for c in domain.constants:
            names.setdefault(c.name, c.types)
    return names


def check_against_problem(src: TomlSource, scene: Scene, domain, problem) -> Scene:
    objects = pddl_objects(domain, problem)
    bodies = []
    for i, b in enumerate(scene.bodies):
        obstacle = b.name not in objects
        if obstacle and not b.fixed:
            raise src.error(f"{b.name!r} is no object of the PDDL problem; an obstacle must say "
                            "`fixed = true`", "objects", i, "name", "objects.name")
        bodies.append(_replace(b, obstacle=obstacle))
    for i, r in enumerate(scene.regions):
        if r.name not in objects:
            raise src.error(f"region {r.name!r} is no object of the PDDL problem", "regions", i,
                            "name", "regions.name")
    return Scene(scene.path, scene.robot, tuple(bodies), scene.regions, scene.camera)


def _replace(body: Body, **changes) -> Body:
    return dataclasses.replace(body, **changes)


def check_modes_against_scene(src: TomlSource | None, scene: Scene, modes, domain, problem):
    """Every PDDL object a geometric action can take must have geometry in the scene.

    For each role (`object`, `on`, `to`) of each geometric mode, the objects
    of the parameter's type need a body or a region. Whether the geometry
    fits the role (grasping a region, say) is left to the symbolic
    preconditions and the optimizer.
    """
    objects = pddl_objects(domain, problem)
    parents = _type_parents(domain)
    for mode in modes.values():
        if not mode.geometric:
            continue
        action = domain.action(mode.action)
        for role in ("object", "on", "to"):
            param = getattr(mode, role)
            if param is None:
                continue
            if param.startswith("?"):
                types = next(p.types for p in action.params if p.name == param)
                candidates = sorted(n for n, t in objects.items()
                                    if any(_is_subtype(tt, types, parents) for tt in t))
            else:
                candidates = [param]
            for name in candidates:
                if scene.has_body(name) or scene.has_region(name):
                    continue
                where = f", {modes.path}:{mode.line}" if mode.line else ""
                message = (f"no object or region {name!r} in the scene, but action "
                           f"{mode.action!r} may {mode.kind} it ({role} = {param}{where})")
                line = src.line("objects") if src is not None else None
                raise SceneError(message, path=scene.path, line=line or 1, key="objects",
                                 source_line=source_line_at(src.text, line or 1)
                                 if src is not None else None)


def entry_error(scene: Scene, message: str, table: str, index: int = 0,
                key: str | None = None) -> SceneError:
    """A SceneError at `key` of the `index`-th `[table]` entry of the scene's file.

    For problems found after parsing (PyBullet refusing a file, a mesh
    without volume): the file is read again for the key's line. A scene
    built in code (no file) is located at the entry's recorded line.
    """
    name = f"{table}.{key}" if key else table
    if scene.path is not None:
        try:
            src = read_toml(scene.path)
        except SceneError:
            src = None
        if src is not None:
            return src.error(message, table, index, key, name)
    entry = scene.robot if table == "robot" else getattr(scene, _TABLES[table])[index]
    return SceneError(message, path=scene.path, line=entry.line, key=name)


_TABLES = {"objects": "bodies", "regions": "regions"}


def body_error(scene: Scene, body: Body, key: str, message: str) -> SceneError:
    """`entry_error` for a body's key, its entry found by name."""
    index = next(i for i, b in enumerate(scene.bodies) if b.name == body.name)
    return entry_error(scene, f"object {body.name!r}: {message}", "objects", index, key)


def _type_parents(domain) -> dict[str, tuple[str, ...]]:
    parents: dict[str, tuple[str, ...]] = {}
    if domain is not None:
        for t in domain.types:
            parents[t.name] = tuple(x for x in t.types if x != t.name)
    return parents


def _is_subtype(t: str, wanted: tuple[str, ...], parents) -> bool:
    seen = set()
    stack = [t]
    while stack:
        cur = stack.pop()
        if cur in wanted or "object" in wanted:
            return True
        if cur in seen:
            continue
        seen.add(cur)
        stack.extend(parents.get(cur, ()))
    return False


def urdf_problem(path: str) -> str | None:
    """Why `path` is no URDF file (not XML, or its root is not <robot>), or None.

    Checked before PyBullet, which prints its parser's complaint on the
    C-level stdout and raises only "Cannot load URDF file".
    """
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as e:
        line, column = e.position
        return f"{path}:{line}:{column + 1}: not a URDF file: XML {str(e).split(':')[0]}"
    except OSError as e:
        return f"cannot read {path}: {e.strerror}"
    if root.tag != "robot":
        return f"{path}: not a URDF file: its root element is <{root.tag}>, not <robot>"
    return None
