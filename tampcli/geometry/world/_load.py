"""Scene bodies and the planar robot into a PyBullet client, with located errors
for the files PyBullet refuses."""

from __future__ import annotations

from tampcli.errors import SceneError
from tampcli.geometry.scene import Body, Scene
from tampcli.geometry.scene_check import body_error, urdf_problem
from tampcli.geometry.shapes import mesh_hulls

PLANAR_COLOR = (0.9, 0.5, 0.1, 1.0)


def load_body(pb, client: int, scene: Scene, body: Body) -> int:
    """The body's unique id in the client (static: mass 0)."""
    pos, orn = body.pose[:3], body.pose[3:]
    if body.shape == "urdf":
        uid = load_urdf(pb, client, body.urdf, pos, orn, body.scale[0],
                        lambda message: body_error(scene, body, "urdf", message))
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
        col, vis = _load_mesh(pb, c, scene, body)
    return pb.createMultiBody(0.0, col, vis, pos, orn, physicsClientId=c)


def _load_mesh(pb, client: int, scene: Scene, body: Body) -> tuple[int, int]:
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
                                   physicsClientId=client)
    except pb.error:
        col = -1
    if col < 0:
        hint = " (an OBJ file needs `v` and `f` lines)" if body.mesh.lower().endswith(
            ".obj") else ""
        raise body_error(scene, body, "mesh", f"PyBullet cannot read the mesh {body.mesh}{hint}")
    return col, vis


def load_urdf(pb, client: int, path, pos, orn, scale: float, error) -> int:
    """loadURDF (fixed base); `error(message)` makes the located SceneError for a file
    it refuses."""
    problem = urdf_problem(path)
    if problem:
        raise error(problem)
    try:
        return pb.loadURDF(path, pos, orn, useFixedBase=True, globalScaling=scale,
                           physicsClientId=client)
    except pb.error as e:
        reason = str(e).rstrip(".")
        raise error(f"PyBullet cannot load {path}: {reason} (a malformed link, or a mesh "
                    "file it names is missing)") from None


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
