"""Arms as data: what a URDF arm needs (file, tool frame, fingers, joints, ready pose),
and the built-in ones a scene names with `model = "..."`.

Every arm's tool frame follows the Panda's: its origin between the
fingertips, 1 cm above them; z pointing out of the gripper (down when
grasping from above); the fingers closing along y.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from tampcli.geometry.urdf_file import pybullet_data_dir

BUNDLED = Path(__file__).resolve().parent / "robots"


@dataclass(frozen=True)
class Fingers:
    """Finger joints (not in q): their values open and closed. Joints that mimic
    one of them in the URDF follow it."""

    joints: tuple[str, ...]
    open: tuple[float, ...]
    closed: tuple[float, ...]


@dataclass(frozen=True)
class Arm:
    """A URDF arm. `urdf`: a path, relative to tampcli's robots/ folder when
    `bundled`, to pybullet_data otherwise, or absolute.

    The tool frame is `tool_link`'s frame moved by `tool_offset` (x, y, z,
    qx, qy, qz, qw), or the frame of the link `tool_frame` (rigidly attached
    to `tool_link`). `joints`: None for the movable non-finger joints from
    the base to `tool_link`.
    """

    urdf: str
    tool_link: str
    joints: tuple[str, ...] | None = None
    fingers: Fingers | None = None
    tool_offset: tuple[float, ...] | None = None
    tool_frame: str | None = None
    ready: tuple[float, ...] | None = None
    bundled: bool = False
    package_paths: tuple[str, ...] = ()

    def path(self) -> str:
        if self.bundled:
            return str(BUNDLED / self.urdf)
        data = pybullet_data_dir()
        if data is None or Path(self.urdf).is_absolute():
            return self.urdf
        return str(data / self.urdf)


PANDA = Arm(
    urdf="franka_panda/panda.urdf",
    tool_link="panda_grasptarget",
    joints=tuple(f"panda_joint{i}" for i in range(1, 8)),
    fingers=Fingers(("panda_finger_joint1", "panda_finger_joint2"), (0.04, 0.04), (0.0, 0.0)),
    ready=(0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785),
)

# pybullet_data's iiwa has no gripper (kuka_with_gripper2.sdf is SDF, with a
# two-stage finger linkage): tampcli's copy adds a parallel gripper like the
# Panda's, boxes on two prismatic joints, and a TCP link 1 cm above the tips.
KUKA_IIWA = Arm(
    urdf="kuka_iiwa_gripper.urdf",
    bundled=True,
    tool_link="lbr_iiwa_link_7",
    tool_frame="gripper_tcp",
    joints=tuple(f"lbr_iiwa_joint_{i}" for i in range(1, 8)),
    fingers=Fingers(("gripper_left_joint",), (0.04,), (0.0,)),
    ready=(0.0, 0.6, 0.0, -1.3, 0.0, 1.24, 0.0),
)

# The xArm gripper is a four-bar linkage: `drive_joint` leads, five joints
# mimic it; 0 is open (8.7 cm between the pads, measured with their 1 mm collision margin), 0.85 closed. The pads'
# tips lie 0.165 m along the gripper base's z axis when open.
XARM6 = Arm(
    urdf="xarm/xarm6_with_gripper.urdf",
    tool_link="xarm_gripper_base_link",
    joints=tuple(f"joint{i}" for i in range(1, 7)),
    tool_offset=(0.0, 0.0, 0.152, 0.0, 0.0, 0.0, 1.0),
    fingers=Fingers(("drive_joint",), (0.0,), (0.85,)),
    ready=(0.0, -0.6, -0.9, 0.0, 1.5, 0.0),
)

ARMS: dict[str, Arm] = {"panda": PANDA, "kuka_iiwa": KUKA_IIWA, "xarm6": XARM6}
