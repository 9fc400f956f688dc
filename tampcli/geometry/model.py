"""The Scene value and its parts (robot, bodies, regions, camera): frozen dataclasses.

Poses are stored as (x, y, z, qx, qy, qz, qw) tuples so that the values
compare and hash; `.matrix` / `.base_pose` give 4x4 arrays.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from tampcli.geometry import transforms
from tampcli.geometry.arms import ARMS, PANDA, Arm, Fingers

SHAPES = ("box", "cylinder", "sphere", "mesh", "urdf")
ROBOT_MODELS = (*ARMS, "planar", "urdf")
PANDA_READY = PANDA.ready

COLORS = {
    "red": (0.85, 0.15, 0.15, 1.0),
    "green": (0.2, 0.7, 0.25, 1.0),
    "blue": (0.2, 0.35, 0.85, 1.0),
    "yellow": (0.95, 0.85, 0.2, 1.0),
    "orange": (0.95, 0.55, 0.1, 1.0),
    "purple": (0.55, 0.25, 0.7, 1.0),
    "cyan": (0.2, 0.8, 0.85, 1.0),
    "magenta": (0.85, 0.2, 0.75, 1.0),
    "pink": (0.95, 0.6, 0.7, 1.0),
    "brown": (0.55, 0.4, 0.3, 1.0),
    "wood": (0.65, 0.5, 0.35, 1.0),
    "white": (0.95, 0.95, 0.95, 1.0),
    "black": (0.1, 0.1, 0.1, 1.0),
    "gray": (0.5, 0.5, 0.5, 1.0),
    "grey": (0.5, 0.5, 0.5, 1.0),
}
DEFAULT_COLOR = (0.6, 0.6, 0.6, 1.0)

@dataclass(frozen=True)
class RobotSpec:
    """The robot: a built-in arm (`panda`, `kuka_iiwa`, `xarm6`), `planar` (a disk
    moving in x, y) or any `urdf` arm (see docs/robots.md)."""

    model: str
    base: tuple[float, ...] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)  # xyz + quat (x, y, z, w)
    start: tuple[float, ...] | None = None
    radius: float = 0.05  # planar only (m)
    height: float = 0.05  # planar only (m)
    urdf: str | None = None  # resolved path (model "urdf")
    tool_link: str | None = None
    joints: tuple[str, ...] | None = None  # None: from the URDF's tree
    tool_offset: tuple[float, ...] | None = None  # xyz + quat in tool_link's frame
    tool_frame: str | None = None  # a link whose frame is the tool frame
    fingers: Fingers | None = None
    package_paths: tuple[str, ...] = ()  # resolved folders
    line: int | None = field(default=None, compare=False)

    @property
    def base_pose(self) -> np.ndarray:
        return transforms.pose_from_xyzquat(self.base)

    @property
    def arm(self) -> Arm | None:
        """The arm to load: a built-in one, or the scene's URDF; None for `planar`."""
        if self.model in ARMS:
            return ARMS[self.model]
        if self.model != "urdf":
            return None
        # Absolute: a relative path (the scene's folder as the command line gave it)
        # would be read as inside pybullet_data, where the built-in arms' are.
        return Arm(urdf=str(Path(self.urdf).resolve()), tool_link=self.tool_link,
                   joints=self.joints,
                   fingers=self.fingers, tool_offset=self.tool_offset,
                   tool_frame=self.tool_frame, package_paths=self.package_paths)


@dataclass(frozen=True)
class Body:
    """A rigid body of the scene. `size`: box extents, cylinder (radius, height), sphere (radius,)."""

    name: str
    shape: str
    size: tuple[float, ...] = ()
    pose: tuple[float, ...] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)  # xyz + quat (x, y, z, w)
    fixed: bool = False
    color: tuple[float, float, float, float] = DEFAULT_COLOR
    mesh: str | None = None  # resolved path of an OBJ file
    urdf: str | None = None  # resolved path of a URDF file
    scale: tuple[float, float, float] = (1.0, 1.0, 1.0)
    obstacle: bool = False  # not named in the PDDL problem
    mass: float | None = None  # kg, for the physics replay; None: from volume and density
    line: int | None = field(default=None, compare=False)

    @property
    def matrix(self) -> np.ndarray:
        """The start pose as a 4x4 matrix."""
        return transforms.pose_from_xyzquat(self.pose)


@dataclass(frozen=True)
class Region:
    """A rectangle on the top face of body `on`, axis-aligned, centred at `center` (x, y)."""

    name: str
    on: str
    center: tuple[float, float]
    size: tuple[float, float]
    color: tuple[float, float, float, float] = (0.3, 0.8, 0.3, 0.5)
    line: int | None = field(default=None, compare=False)

    @property
    def lower(self) -> np.ndarray:
        return np.array(self.center) - 0.5 * np.array(self.size)

    @property
    def upper(self) -> np.ndarray:
        return np.array(self.center) + 0.5 * np.array(self.size)


@dataclass(frozen=True)
class Camera:
    eye: tuple[float, float, float]
    target: tuple[float, float, float]
    up: tuple[float, float, float] = (0.0, 0.0, 1.0)
    fov: float = 50.0  # degrees, vertical


@dataclass(frozen=True)
class Scene:
    path: str | None
    robot: RobotSpec
    bodies: tuple[Body, ...] = ()
    regions: tuple[Region, ...] = ()
    camera: Camera | None = None

    def body(self, name: str) -> Body:
        for b in self.bodies:
            if b.name == name:
                return b
        raise KeyError(name)

    def region(self, name: str) -> Region:
        for r in self.regions:
            if r.name == name:
                return r
        raise KeyError(name)

    def has_body(self, name: str) -> bool:
        return any(b.name == name for b in self.bodies)

    def has_region(self, name: str) -> bool:
        return any(r.name == name for r in self.regions)

    @property
    def movable_names(self) -> tuple[str, ...]:
        return tuple(b.name for b in self.bodies if not b.fixed)
