"""Scene bodies, URDF files and the planar robot into a PyBullet client, with located
errors for the files PyBullet refuses or whose meshes are nowhere to be found."""

from __future__ import annotations

import os
import sys
import tempfile
from contextlib import contextmanager
from pathlib import Path

from tampcli.errors import SceneError
from tampcli.geometry.scene import Body, Scene
from tampcli.geometry.scene_check import body_error, urdf_problem
from tampcli.geometry.shapes import mesh_hulls
from tampcli.geometry.urdf_file import resolved_copy

PLANAR_COLOR = (0.9, 0.5, 0.1, 1.0)


def load_body(pb, client: int, scene: Scene, body: Body, visuals: bool = True) -> int:
    """The body's unique id in the client (static: mass 0); `visuals` False: without
    the shapes only images need (a mesh's, a URDF's <visual> elements)."""
    pos, orn = body.pose[:3], body.pose[3:]
    if body.shape == "urdf":
        uid = load_urdf(pb, client, body.urdf, pos, orn, body.scale[0],
                        lambda message: body_error(scene, body, "urdf", message),
                        visuals=visuals)
        if visuals:
            pb.changeVisualShape(uid, -1, rgbaColor=body.color, physicsClientId=client)
        return uid
    c = client
    if body.shape == "box":
        half = [s / 2 for s in body.size]
        col = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=half, physicsClientId=c)
        vis = pb.createVisualShape(pb.GEOM_BOX, halfExtents=half, rgbaColor=body.color,
                                   physicsClientId=c)
    elif body.shape == "cylinder":
        r, h = body.size
        col = pb.createCollisionShape(pb.GEOM_CYLINDER, radius=r, height=h, physicsClientId=c)
        vis = pb.createVisualShape(pb.GEOM_CYLINDER, radius=r, length=h,
                                   rgbaColor=body.color, physicsClientId=c)
    elif body.shape == "sphere":
        col = pb.createCollisionShape(pb.GEOM_SPHERE, radius=body.size[0], physicsClientId=c)
        vis = pb.createVisualShape(pb.GEOM_SPHERE, radius=body.size[0],
                                   rgbaColor=body.color, physicsClientId=c)
    else:
        col, vis = _load_mesh(pb, c, scene, body, visuals)
    return pb.createMultiBody(0.0, col, vis, pos, orn, physicsClientId=c)


def _load_mesh(pb, client: int, scene: Scene, body: Body, visuals: bool) -> tuple[int, int]:
    """Collision and visual shapes of a mesh body; a file either reader refuses is a
    SceneError at the body's `mesh` key.

    The file is read (and its hulls built, cached for the collision checker)
    before PyBullet sees it: that names what is wrong, where PyBullet only
    says that it failed.
    """
    try:
        mesh_hulls(body.mesh, body.scale)
    except SceneError as e:
        raise body_error(scene, body, "mesh", f"{e.location()}: {e.message}") from None
    try:
        col = pb.createCollisionShape(pb.GEOM_MESH, fileName=body.mesh,
                                      meshScale=list(body.scale), physicsClientId=client)
        vis = pb.createVisualShape(pb.GEOM_MESH, fileName=body.mesh,
                                   meshScale=list(body.scale), rgbaColor=body.color,
                                   physicsClientId=client) if visuals else -1
    except pb.error:
        col = -1
    if col < 0:
        hint = " (an OBJ file needs `v` and `f` lines)" if body.mesh.lower().endswith(
            ".obj") else ""
        raise body_error(scene, body, "mesh", f"PyBullet cannot read the mesh {body.mesh}{hint}")
    return col, vis


def load_urdf(pb, client: int, path, pos, orn, scale: float, error,
              package_paths=(), hint: str = "", visuals: bool = True) -> int:
    """loadURDF (fixed base); `error(message)` makes the located SceneError for a file
    it refuses, or a mesh it names that is nowhere to be found. `visuals` False:
    loaded without its <visual> elements (urdf_file.resolved_copy).

    Mesh paths PyBullet would not find itself (`package://`, or beside a
    copy of the file) are made absolute in a temporary copy; what PyBullet
    prints on the C-level terminal is kept off it, and its last complaint
    joins the message when it refuses the file.
    """
    text, problem = None, urdf_problem(path)
    if problem is None:
        try:
            text, problem = resolved_copy(path, package_paths, hint, visuals)
        except ValueError as e:
            problem = str(e)
    if problem:
        raise error(problem)
    with tempfile.TemporaryDirectory(prefix="tampcli-urdf-") as folder:
        target = path
        if text is not None:
            target = str(Path(folder) / Path(path).name)
            Path(target).write_text(text, encoding="utf-8")
        with _quiet_c_output() as printed:
            try:
                # Cylinders as cylinders: by default PyBullet turns a URDF's <cylinder>
                # into a mesh it names "unknown_file", which no query here can read
                # (blind28 p05: an arm's cylinder links were in no collision pair).
                return pb.loadURDF(target, pos, orn, useFixedBase=True, globalScaling=scale,
                                   flags=pb.URDF_USE_IMPLICIT_CYLINDER,
                                   physicsClientId=client)
            except pb.error as e:
                reason = str(e).rstrip(".")
        said = _complaint(printed)
        raise error(f"PyBullet cannot load {path}: {reason}"
                    + (f" ({said})" if said else " (a malformed link or joint)"))


@contextmanager
def _quiet_c_output():
    """Send fds 1 and 2 to a file while the block runs; yield the list of lines
    written (filled when the block ends)."""
    printed: list[str] = []
    sys.stdout.flush()
    sys.stderr.flush()
    try:
        saved = (os.dup(1), os.dup(2))
    except OSError:  # no terminal descriptors to guard
        yield printed
        return
    with tempfile.TemporaryFile() as sink:
        try:
            os.dup2(sink.fileno(), 1)
            os.dup2(sink.fileno(), 2)
            yield printed
        finally:
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            for fd in saved:
                os.close(fd)
            sink.seek(0)
            printed.extend(sink.read().decode("utf-8", errors="replace").splitlines())


def _complaint(lines: list[str]) -> str:
    """The last line of PyBullet's output that says something (not a source location)."""
    said = [line.removeprefix("b3Printf:").strip() for line in lines]
    said = [line for line in said if line and not line.startswith(("b3Warning[", "b3Error["))
            and "build time" not in line]
    return said[-1] if said else ""


def make_planar(pb, client: int, radius: float, height: float, z: float) -> int:
    """A vertical cylinder on two prismatic joints (x, then y) above the origin."""
    col = pb.createCollisionShape(pb.GEOM_CYLINDER, radius=radius, height=height,
                                  physicsClientId=client)
    vis = pb.createVisualShape(pb.GEOM_CYLINDER, radius=radius, length=height,
                               rgbaColor=PLANAR_COLOR, physicsClientId=client)
    return pb.createMultiBody(
        0.0, -1, -1, [0.0, 0.0, z], linkMasses=[0.1, 0.1],
        linkCollisionShapeIndices=[-1, col], linkVisualShapeIndices=[-1, vis],
        linkPositions=[[0, 0, 0]] * 2, linkOrientations=[[0, 0, 0, 1]] * 2,
        linkInertialFramePositions=[[0, 0, 0]] * 2,
        linkInertialFrameOrientations=[[0, 0, 0, 1]] * 2, linkParentIndices=[0, 1],
        linkJointTypes=[pb.JOINT_PRISMATIC] * 2, linkJointAxis=[[1, 0, 0], [0, 1, 0]],
        physicsClientId=client)
