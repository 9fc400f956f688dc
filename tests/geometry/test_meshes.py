import struct

import numpy as np
import pytest

from tampcli.errors import SceneError
from tampcli.geometry.meshes import read_mesh_parts
from tampcli.geometry.shapes import mesh_hulls

CUBE = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
CUBE_FACES = [(1, 2, 4, 3), (5, 7, 8, 6), (1, 5, 6, 2), (3, 4, 8, 7), (1, 3, 7, 5), (2, 6, 8, 4)]


def _obj(path, offsets):
    lines, base = [], 0
    for k, off in enumerate(offsets):
        lines.append(f"o part{k}")
        lines += [f"v {x + off} {y} {z}" for x, y, z in CUBE]
        lines += ["f " + " ".join(f"{base + i}/1/1" for i in face) for face in CUBE_FACES]
        base += 8
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def test_obj_objects_become_separate_parts(tmp_path):
    parts = read_mesh_parts(_obj(tmp_path / "two.obj", [0.0, 3.0]))
    assert len(parts) == 2
    np.testing.assert_allclose(parts[1].min(axis=0), [3, 0, 0])
    hulls = mesh_hulls(str(tmp_path / "two.obj"), (0.5, 0.5, 0.5))
    assert len(hulls) == 2 and hulls[0].vertices.max() == pytest.approx(0.5)


def test_binary_and_ascii_stl(tmp_path):
    tris = [((0, 0, 0), (1, 0, 0), (0, 1, 0)), ((0, 0, 0), (0, 1, 0), (0, 0, 1)),
            ((0, 0, 0), (0, 0, 1), (1, 0, 0)), ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    binary = bytearray(b"solid-looking header".ljust(80, b" ")) + struct.pack("<I", len(tris))
    for t in tris:
        binary += struct.pack("<3f", 0, 0, 0) + struct.pack("<9f", *sum(t, ())) + b"\0\0"
    (tmp_path / "t.stl").write_bytes(bytes(binary))
    ascii_text = "solid t\n" + "".join(
        "facet normal 0 0 0\nouter loop\n" + "".join(f"vertex {x} {y} {z}\n" for x, y, z in t)
        + "endloop\nendfacet\n" for t in tris) + "endsolid t\n"
    (tmp_path / "a.stl").write_text(ascii_text)
    for name in ("t.stl", "a.stl"):
        (part,) = read_mesh_parts(str(tmp_path / name))
        assert len(part) == 4


def test_bad_meshes_are_scene_errors(tmp_path):
    (tmp_path / "bad.obj").write_text("v 0 0 0\nv 1 x 0\n")
    with pytest.raises(SceneError) as info:
        read_mesh_parts(str(tmp_path / "bad.obj"))
    assert info.value.line == 2
    (tmp_path / "flat.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3 4\n")
    with pytest.raises(SceneError):
        mesh_hulls(str(tmp_path / "flat.obj"))
    with pytest.raises(SceneError):
        read_mesh_parts(str(tmp_path / "model.dae"))
    with pytest.raises(SceneError):
        read_mesh_parts(str(tmp_path / "missing.obj"))
