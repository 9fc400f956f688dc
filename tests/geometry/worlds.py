"""Small scenes built in code for the geometry tests, and PyBullet's side of a World."""

from dataclasses import dataclass

from tampcli.geometry.scene import Body, RobotSpec, Scene

IDENTITY = (0.0, 0.0, 0.0, 1.0)


def box(name, size, xyz, fixed=True, quat=IDENTITY):
    return Body(name, "box", tuple(size), tuple(xyz) + tuple(quat), fixed)


def panda_scene() -> Scene:
    """A Panda on a pedestal, a table, a wall, a cylinder, a sphere and a cube to pick."""
    bodies = (
        box("pedestal", (0.3, 0.3, 0.2), (0.0, 0.0, -0.1)),
        box("table", (0.8, 1.2, 0.04), (0.55, 0.0, -0.02)),
        box("wall", (0.05, 0.8, 0.6), (0.75, 0.0, 0.3)),
        Body("post", "cylinder", (0.05, 0.3), (0.4, 0.35, 0.15) + IDENTITY, True),
        Body("ball", "sphere", (0.08,), (0.3, -0.35, 0.45) + IDENTITY, True),
        box("a", (0.05, 0.05, 0.05), (0.45, -0.1, 0.025), fixed=False,
            quat=(0.0, 0.0, 0.3826834, 0.9238795)),
    )
    return Scene(None, RobotSpec("panda"), bodies)


def planar_scene() -> Scene:
    bodies = (
        box("floor", (2.0, 2.0, 0.02), (0.0, 0.0, -0.01)),
        box("wall", (0.05, 1.0, 0.2), (0.3, 0.0, 0.1)),
        Body("post", "cylinder", (0.06, 0.2), (-0.3, 0.3, 0.1) + IDENTITY, True),
        box("a", (0.06, 0.06, 0.05), (-0.2, -0.3, 0.025), fixed=False),
    )
    return Scene(None, RobotSpec("planar", base=(0.0, 0.0, 0.025) + IDENTITY), bodies)


def kuka_scene() -> Scene:
    """Any URDF arm (the KUKA iiwa of pybullet_data, STL collision meshes), a URDF table
    obstacle, a V-HACD mesh (5 convex parts) and an OBJ cube."""
    import pybullet_data

    data = pybullet_data.getDataPath()
    robot = RobotSpec("urdf", urdf=f"{data}/kuka_iiwa/model.urdf", tool_link="lbr_iiwa_link_7",
                      joints=tuple(f"lbr_iiwa_joint_{i}" for i in range(1, 8)))
    bodies = (
        Body("table", "urdf", pose=(0.9, 0.0, -0.62) + IDENTITY, fixed=True,
             urdf=f"{data}/table/table.urdf"),
        Body("duck", "mesh", pose=(0.0, 0.55, 0.3) + IDENTITY, fixed=True,
             mesh=f"{data}/duck_vhacd.obj", scale=(0.1, 0.1, 0.1)),
        Body("cube", "mesh", pose=(-0.5, -0.3, 0.4) + IDENTITY, fixed=True,
             mesh=f"{data}/cube.obj", scale=(0.1, 0.1, 0.1)),
    )
    return Scene(None, robot, bodies)


@dataclass(frozen=True)
class Simulator:
    """The PyBullet client behind a World and the ids of what it loaded: World keeps
    them private, tests reach for them only to hold our answers against PyBullet's."""

    pb: object
    client: int
    robot: int
    bodies: dict
    fingers: tuple


def simulator(world) -> Simulator:
    return Simulator(world._pb, world._client, world._robot, dict(world._bodies),
                     world._fingers.pb if world._fingers else ())
