"""Mesh files -> vertex sets, split the way PyBullet splits them into convex parts.

PyBullet makes one convex hull per shape of an OBJ file (a new shape at each
`o` or `g` line that has faces: how V-HACD decompositions are stored) and one
hull for an STL file. Only the vertices the faces use belong to a part.
"""

from __future__ import annotations

import struct

import numpy as np

from tampcli.errors import SceneError


def read_mesh_parts(path: str) -> list[np.ndarray]:
    """Vertex arrays (k, 3), one per convex part."""
    lower = path.lower()
    if lower.endswith(".obj"):
        parts = _obj_parts(path)
    elif lower.endswith(".stl"):
        parts = [_stl_vertices(path)]
    else:
        raise SceneError("unsupported mesh format: use .obj or .stl", path=path)
    parts = [p for p in parts if len(p) >= 4]
    if not parts:
        raise SceneError("a mesh needs at least 4 vertices", path=path)
    return parts


def _read_text(path: str) -> list[str]:
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return f.read().splitlines()
    except OSError as e:
        raise SceneError(f"cannot read mesh: {e.strerror}", path=path) from None


def _obj_parts(path: str) -> list[np.ndarray]:
    vertices: list[list[float]] = []
    groups: list[set[int]] = [set()]
    for number, line in enumerate(_read_text(path), start=1):
        head, _, rest = line.strip().partition(" ")
        try:
            if head == "v":
                vertices.append([float(v) for v in rest.split()[:3]])
                if len(vertices[-1]) != 3:
                    raise ValueError
            elif head == "f":
                n = len(vertices)
                for token in rest.split():
                    index = int(token.split("/")[0])
                    groups[-1].add(index - 1 if index > 0 else n + index)
            elif head in ("o", "g") and groups[-1]:
                groups.append(set())
        except ValueError:
            raise SceneError(f"bad {head!r} line: {line.strip()!r}", path=path,
                             line=number) from None
    points = np.array(vertices, dtype=float).reshape(-1, 3)
    used = [sorted(i for i in g if 0 <= i < len(points)) for g in groups if g]
    if not used:  # a point cloud without faces: one hull of everything
        return [points]
    return [points[idx] for idx in used]


def _stl_vertices(path: str) -> np.ndarray:
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise SceneError(f"cannot read mesh: {e.strerror}", path=path) from None
    if len(data) >= 84:
        (count,) = struct.unpack_from("<I", data, 80)
        if 84 + 50 * count == len(data):
            records = np.frombuffer(data, dtype=np.dtype([
                ("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")]),
                count=count, offset=84)
            return np.unique(records["v"].reshape(-1, 3).astype(float), axis=0)
    rows = []
    for line in data.decode("utf-8", errors="replace").splitlines():
        parts = line.split()
        if parts[:1] == ["vertex"] and len(parts) >= 4:
            try:
                rows.append([float(v) for v in parts[1:4]])
            except ValueError:
                raise SceneError(f"bad vertex line {line.strip()!r}", path=path) from None
    return np.unique(np.array(rows, dtype=float).reshape(-1, 3), axis=0)
