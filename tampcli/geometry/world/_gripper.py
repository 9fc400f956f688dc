"""What a World tells of its robot's gripper: the finger joints and their range, and
the open hand's opening, span and depth as measured on its collision shapes when the
robot was loaded (_measure.gripper_size). A base of World: it reads World's
`_fingers`, `_gripper`, `chain` and PyBullet handles."""

from __future__ import annotations

from tampcli.geometry.world import _measure


class GripperQueries:
    @property
    def finger_names(self) -> tuple[str, ...]:
        """The gripper's finger joints (not in q: they open and close, never plan)."""
        return self._fingers.names if self._fingers else ()

    @property
    def finger_range(self) -> tuple[tuple[float, float], ...]:
        """(open, closed) value of each joint of `finger_names`."""
        if self._fingers is None:
            return ()
        k = len(self._fingers.names)
        return tuple(zip(self._fingers.open[:k], self._fingers.closed[:k], strict=True))

    def finger_values(self, named) -> tuple[float, ...]:
        """Every finger joint's value (`finger_links`' order) from `finger_names`' (a
        file's columns): a joint that mimics one goes the same fraction of its travel."""
        return self._fingers.expand(named)

    @property
    def finger_links(self) -> tuple[int, ...]:
        """Chain index of the link each finger joint moves, in the order of
        `set_state`'s `fingers` (the named joints first, then those mimicking them)."""
        if self._fingers is None:
            return ()
        by_pb = {link.pb_index: i for i, link in enumerate(self.chain.links)}
        return tuple(by_pb[j] for j in self._fingers.pb)

    @property
    def gripper_opening(self) -> float | None:
        """Gap (m) between the open fingers along the tool's y axis, near the tool
        origin: the widest object they close on. None without fingers."""
        return self._gripper[0] if self._gripper else None

    def gripper_at(self, t: float) -> tuple[tuple[float, ...], float, float] | None:
        """(finger joint values in `finger_links`' order, opening, fingertip depth) with
        the fingers a fraction t of the way from open (0) to closed (1), measured as
        `gripper_opening` and `fingertip_depth` are. None without fingers."""
        if self._fingers is None:
            return None
        values = self._fingers.at(float(t))
        size = _measure.gripper_size(self._pb, self._client, self._robot, self._fingers,
                                     self.chain, self._tool_index, self.start,
                                     values=dict(zip(self.finger_links, values, strict=True)))
        if size is None:
            return None
        return values, size[0], size[1]

    @property
    def finger_span(self) -> tuple[float, float] | None:
        """(inner, outer): how far the open fingers' near and far sides stand from the
        tool's axis along its y axis, near the tool origin (the Panda's: 3.9 and 6.7
        cm, the far side its finger hull's widest). None without fingers."""
        return self._gripper[2] if self._gripper else None

    @property
    def fingertip_depth(self) -> float | None:
        """How far (m) the open fingertips reach beyond the tool origin along the
        tool's z axis (the Panda's: 1 cm). None without fingers."""
        return self._gripper[1] if self._gripper else None
