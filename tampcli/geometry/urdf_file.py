"""A URDF file read as a tree (links, joints, mimic relations) and its mesh paths resolved.

PyBullet resolves a mesh path against the URDF's own folder only, and says
no more than "cannot load" (after raw warnings on the terminal) when that
fails. Reading the file first finds the arm's joints from its tree and
names the mesh that is missing, and where it was looked for.

A mesh path `package://PKG/rest` or a relative `rest` is looked for beside
the URDF, then in pybullet_data, then in each of the scene's
`package_paths`; a package folder PKG may sit at the top of such a place or
one level down (pybullet_data keeps `xarm/xarm_description`).
"""

from __future__ import annotations

import importlib.util
from dataclasses import dataclass
from pathlib import Path
from xml.etree import ElementTree

MOVABLE = ("revolute", "continuous", "prismatic")
PACKAGE = "package://"


@dataclass(frozen=True)
class UrdfJoint:
    name: str
    kind: str  # revolute | continuous | prismatic | fixed | ...
    parent: str
    child: str
    mimic: tuple[str, float, float] | None = None  # (joint, multiplier, offset)

    @property
    def movable(self) -> bool:
        return self.kind in MOVABLE


@dataclass(frozen=True)
class Urdf:
    path: str
    links: tuple[str, ...]
    joints: tuple[UrdfJoint, ...]
    meshes: tuple[str, ...]  # every <mesh filename>, as written

    def joint(self, name: str) -> UrdfJoint | None:
        return next((j for j in self.joints if j.name == name), None)

    def path_to(self, link: str) -> list[UrdfJoint]:
        """The joints from the root link down to `link`, root first."""
        by_child = {j.child: j for j in self.joints}
        out = []
        while link in by_child:
            joint = by_child[link]
            out.append(joint)
            link = joint.parent
        return out[::-1]

    def arm_joints(self, tool_link: str, exclude=()) -> tuple[str, ...]:
        """Movable joints from the base to `tool_link` (chain order), without mimic
        joints and those in `exclude` (fingers)."""
        return tuple(j.name for j in self.path_to(tool_link)
                     if j.movable and j.mimic is None and j.name not in exclude)

    def followers(self, leaders) -> dict[str, tuple[str, float, float]]:
        """Joints that mimic one of `leaders`, directly or through another follower:
        name -> (leader, multiplier, offset) composed down to the leader."""
        out: dict[str, tuple[str, float, float]] = {}
        changed = True
        while changed:
            changed = False
            for j in self.joints:
                if j.mimic is None or j.name in out or j.name in leaders:
                    continue
                target, mult, off = j.mimic
                if target in leaders:
                    out[j.name] = (target, mult, off)
                elif target in out:
                    lead, m2, o2 = out[target]
                    out[j.name] = (lead, mult * m2, mult * o2 + off)
                else:
                    continue
                changed = True
        return out


def read_urdf(path: str) -> Urdf:
    """The tree of a URDF file; a ValueError says why it is none (PyBullet's checks
    come later)."""
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as e:
        line, column = e.position
        raise ValueError(f"{path}:{line}:{column + 1}: not a URDF file: XML "
                         f"{str(e).split(':')[0]}") from None
    except OSError as e:
        raise ValueError(f"cannot read {path}: {e.strerror}") from None
    if root.tag != "robot":
        raise ValueError(f"{path}: not a URDF file: its root element is <{root.tag}>, "
                         "not <robot>")
    links = tuple(e.get("name", "") for e in root.findall("link"))
    joints = []
    for e in root.findall("joint"):
        parent, child, mimic = e.find("parent"), e.find("child"), e.find("mimic")
        if parent is None or child is None:
            raise ValueError(f"{path}: joint {e.get('name')!r} needs <parent> and <child>")
        follows = None
        if mimic is not None:
            follows = (mimic.get("joint", ""), _float(mimic.get("multiplier"), 1.0, path),
                       _float(mimic.get("offset"), 0.0, path))
        joints.append(UrdfJoint(e.get("name", ""), e.get("type", ""), parent.get("link", ""),
                                child.get("link", ""), follows))
    meshes = tuple(m.get("filename", "") for m in root.iter("mesh"))
    return Urdf(path, links, tuple(joints), meshes)


def _float(text: str | None, default: float, path: str) -> float:
    if text is None:
        return default
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"{path}: <mimic> expects a number, got {text!r}") from None


def pybullet_data_dir() -> Path | None:
    """pybullet_data's folder, found without importing it (PyBullet stays in the World)."""
    spec = importlib.util.find_spec("pybullet_data")
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(next(iter(spec.submodule_search_locations)))


def search_roots(urdf_path: str, package_paths=()) -> list[Path]:
    """Where mesh paths are looked for, in order."""
    roots = [Path(urdf_path).resolve().parent]
    data = pybullet_data_dir()
    if data is not None:
        roots.append(data)
    roots.extend(Path(p) for p in package_paths)
    return roots


def resolve_mesh(filename: str, roots) -> Path | None:
    """The file a URDF's mesh path names, or None when no root holds it."""
    if not filename.startswith(PACKAGE) and Path(filename).is_absolute():
        return Path(filename) if Path(filename).is_file() else None
    rest = filename[len(PACKAGE):] if filename.startswith(PACKAGE) else filename
    for root in roots:
        candidate = root / rest
        if candidate.is_file():
            return candidate
        if filename.startswith(PACKAGE) and root.is_dir():
            for sub in sorted(p for p in root.iterdir() if p.is_dir()):
                if (sub / rest).is_file():
                    return sub / rest
    return None


def resolved_copy(urdf_path: str, package_paths=(), hint: str = "", visuals: bool = True,
                  ) -> tuple[str | None, str | None]:
    """(text of a copy of the URDF whose mesh paths are absolute, or None when PyBullet
    finds every mesh itself; the problem, or None).

    The problem names the first mesh no search root holds, with the line of
    the URDF that names it. `visuals` False: the copy has no <visual> element
    (a copy always), every mesh still looked for, so a file is refused or taken
    the same either way.
    """
    roots = search_roots(urdf_path, package_paths)
    text = Path(urdf_path).read_text(encoding="utf-8", errors="replace")
    here = roots[0]
    found_all, copy = {}, False
    for filename in dict.fromkeys(read_urdf(urdf_path).meshes):
        found = resolve_mesh(filename, roots)
        if found is None:
            line = _line_of(text, filename)
            where = ", ".join(str(r) for r in roots)
            return None, f"{urdf_path}:{line}: mesh {filename!r} not found (looked in {where}{hint})"
        found_all[filename] = str(found.resolve())
        # PyBullet itself strips `package://` and looks beside the URDF only.
        copy = copy or not (here / filename.removeprefix(PACKAGE)).is_file()
    if visuals and not copy:
        return None, None
    if not visuals:  # stripped only now: a missing mesh's line is the file's own
        text = without_visuals(text)
    # The copy lives elsewhere: every mesh path in it must be absolute.
    for old, new in found_all.items():
        text = text.replace(f'"{old}"', f'"{new}"').replace(f"'{old}'", f"'{new}'")
    return text, None


def without_visuals(text: str) -> str:
    """The URDF `text` without its links' <visual> elements: what PyBullet loads
    for rendering alone (a Panda's visual meshes: 0.15 of its 0.17 s load)."""
    root = ElementTree.fromstring(text)
    for link in root.iter("link"):
        for visual in link.findall("visual"):
            link.remove(visual)
    return ElementTree.tostring(root, encoding="unicode")


def _line_of(text: str, needle: str) -> int:
    for number, line in enumerate(text.splitlines(), start=1):
        if needle in line:
            return number
    return 1
