"""A solution.json as a function of time: robot joints, object poses, fingers
and caption for every video frame.

Timing is even in joint space: each trajectory segment lasts its joint-space
length divided by one speed, so the robot neither rushes through sparse
waypoints nor crawls through dense ones. Each instantaneous action (grasp,
place, a symbolic action) and the start of a push get a short pause; the
video also holds its first and last states.

The held object follows the tool: during a phase with `attached = a`, a's pose
is tool_pose(q) @ G with G = inv(tool_pose(q_start)) @ (a's pose at the
phase's start boundary). Everything else rests at its phase-boundary pose.
Kinematics enter as a plain `tool_pose(q) -> 4x4` callable, so this module
needs no simulator.
"""

from __future__ import annotations

import bisect
import dataclasses
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from tampcli.geometry.transforms import pose_from_xyzquat, pose_inverse
from tampcli.optimize.kinds import KINDS
from tampcli.search.plan_text import parse_step
from tampcli.solution import Solution

# Default joint-space speeds: a Panda joint vector moving at 1 rad/s looks
# unhurried; a planar disk at 0.25 m/s likewise.
DEFAULT_SPEED = {"planar": 0.25}
DEFAULT_SPEED_OTHER = 1.0
AUTO_MOTION_SECONDS = (1.0, 30.0)


@dataclass(frozen=True)
class FrameState:
    """What one frame shows. `poses`: movable object name -> 4x4 world pose."""

    t: float
    q: tuple[float, ...]
    poses: dict
    fingers_closed: bool
    label: str  # "move", "carry a", "(pick a table)", "start", "done"
    step: int
    steps: int
    held: str | None = None  # the object carried in a grasp (not a pushed one)
    fingers: tuple[float, ...] | None = None  # each finger joint's value, when the file gives


@dataclass(frozen=True)
class _Item:
    """A stretch of the timeline: a move along segment (i, i+1), or a hold."""

    moving: bool  # along a segment of the trajectory, or holding still
    phase: int  # index into phases; -1 = before the first, len(phases) = after the last
    index: int  # waypoint (start of the segment for a move)
    duration: float


def phase_label(phase) -> str:
    """The caption of a phase: its action, or the motion it is (label: free or carrying)."""
    if phase.action is not None:
        return phase.action
    return f"carry {phase.attached}" if phase.attached is not None else "move"  # label


def schema_of(action: str) -> str:
    """`"(pick a table)"` -> `"pick"` (plan_text.parse_step reads it)."""
    return parse_step(action).action


class Replay:
    """The states of a solution over time (seconds from the first frame)."""

    def __init__(self, solution: Solution, tool_pose: Callable[[np.ndarray], np.ndarray],
                 *, mode_kind: Callable[[str], str | None] | None = None,
                 duration: float | None = None, speed: float | None = None,
                 pause: float = 0.4, fingers=None):
        """`fingers`: per waypoint, each finger joint's value (a solution file's finger
        columns); they override the open/closed rule of the actions."""
        if not solution.trajectory:
            raise ValueError("a replay needs a trajectory")
        self.solution = solution
        self.q = np.asarray(solution.trajectory, dtype=float)
        self._finger_values = None if fingers is None else np.asarray(fingers, dtype=float)
        self.phases = solution.phases
        mode_kind = mode_kind or (lambda action: None)
        # Per phase: its action's kind (optimize.kinds); None for a motion or
        # when the modes are unknown.
        names = [mode_kind(p.action) if p.action is not None else None for p in self.phases]
        self._kinds = [None if name is None else KINDS[name] for name in names]
        self._boundary = {name: [pose_from_xyzquat(p) for p in poses]
                          for name, poses in solution.objects.items()}
        self._grasp = self._grasp_transforms(tool_pose)
        self._tool_pose = tool_pose
        self._closed_before, self._closed_after = self._finger_states()
        self.steps = sum(1 for p in self.phases if p.action is not None) or len(solution.plan)
        self._step = self._step_numbers()
        self.speed = self._speed(duration, speed)
        self.items = self._timeline(pause)
        self._ends = [float(v) for v in np.cumsum([item.duration for item in self.items])]
        self.duration = float(self._ends[-1]) if self._ends else 0.0

    def fingers_at(self, index: int) -> tuple[float, ...] | None:
        """The finger joints' values the solution gives at waypoint `index` (None:
        it gives none)."""
        if self._finger_values is None:
            return None
        return tuple(float(v) for v in self._finger_values[index])

    # -- building ---------------------------------------------------------------

    def _grasp_transforms(self, tool_pose) -> dict[int, np.ndarray]:
        grasp = {}
        for k, phase in enumerate(self.phases):
            if phase.attached is not None and phase.attached in self._boundary:
                start = tool_pose(self.q[phase.start])
                grasp[k] = pose_inverse(start) @ self._boundary[phase.attached][k]
        return grasp

    def _finger_states(self) -> tuple[list[bool], list[bool]]:
        """Closed before/after each phase. A carrying motion closes them, a free
        one opens them; a push or a move action keeps them as they were; an
        instantaneous action switches them by its mode, or, mode unknown, by its
        `attached` (the object held once it is done, as the optimizer writes it)."""
        before, after = [], []
        closed = False
        for phase, kind in zip(self.phases, self._kinds, strict=True):
            before.append(closed)
            if phase.action is None:
                closed = phase.attached is not None
                before[-1] = closed
            elif phase.start == phase.end:
                if kind is None:
                    closed = phase.attached is not None
                elif kind.fingers is not None:
                    closed = kind.fingers
            after.append(closed)
        return before, after

    def _step_numbers(self) -> list[int]:
        steps, done = [], 0
        for phase in self.phases:
            if phase.action is not None:
                done += 1
                steps.append(done)
            else:
                steps.append(min(done + 1, self.steps))
        return steps

    def _speed(self, duration, speed) -> float:
        length = self._motion_length()
        if length == 0.0:
            return 1.0
        if duration is not None:
            return length / duration
        if speed is not None:
            return speed
        model = str(self.solution.robot.get("model", ""))
        nominal = DEFAULT_SPEED.get(model, DEFAULT_SPEED_OTHER)
        lo, hi = AUTO_MOTION_SECONDS
        return length / min(max(length / nominal, lo), hi)

    def _motion_length(self) -> float:
        return float(np.linalg.norm(np.diff(self.q, axis=0), axis=1).sum()) if len(self.q) > 1 \
            else 0.0

    def _timeline(self, pause: float) -> list[_Item]:
        items = [_Item(False, -1, 0, pause)]
        for k, phase in enumerate(self.phases):
            if phase.action is not None:
                items.append(_Item(False, k, phase.start, pause))
            for i in range(phase.start, phase.end):
                length = float(np.linalg.norm(self.q[i + 1] - self.q[i]))
                items.append(_Item(True, k, i, length / self.speed))
        if not self.phases:  # a bare trajectory: one motion through it
            for i in range(len(self.q) - 1):
                length = float(np.linalg.norm(self.q[i + 1] - self.q[i]))
                items.append(_Item(True, 0, i, length / self.speed))
        items.append(_Item(False, len(self.phases), len(self.q) - 1, pause))
        return [item for item in items if item.duration > 0.0] or [items[0]]

    # -- querying ---------------------------------------------------------------

    def frame_count(self, fps: float) -> int:
        return int(round(self.duration * fps)) + 1

    def states(self, fps: float) -> list[FrameState]:
        """One state per frame, evenly spaced, first and last states included."""
        n = self.frame_count(fps)
        if n == 1:
            return [self.state_at(0.0)]
        return [self.state_at(self.duration * f / (n - 1)) for f in range(n)]

    def state_at(self, t: float) -> FrameState:
        j = min(bisect.bisect_right(self._ends, t), len(self.items) - 1)
        item = self.items[j]
        start = self._ends[j] - item.duration
        alpha = 0.0 if item.duration == 0 else min(max((t - start) / item.duration, 0.0), 1.0)
        if item.moving:
            q = (1.0 - alpha) * self.q[item.index] + alpha * self.q[item.index + 1]
            return self._with_fingers(self._state(t, q, item.phase, after=False), item.index,
                                      alpha)
        # An instantaneous action switches half-way through its pause; the
        # pause before a push shows its start.
        switches = 0 <= item.phase < len(self.phases) and \
            self.phases[item.phase].start == self.phases[item.phase].end
        state = self._state(t, self.q[item.index], item.phase, after=switches and alpha >= 0.5)
        return self._with_fingers(state, item.index, 0.0)

    def _with_fingers(self, state: FrameState, index: int, alpha: float) -> FrameState:
        if self._finger_values is None:
            return state
        f = self._finger_values[index] if alpha == 0.0 else \
            (1.0 - alpha) * self._finger_values[index] + alpha * self._finger_values[index + 1]
        return dataclasses.replace(state, fingers=tuple(float(v) for v in f))

    def keyframes(self) -> list[FrameState]:
        """The state just after each geometric action: one strip panel each."""
        return [self._with_fingers(self._state(0.0, self.q[phase.end], k, after=True),
                                   phase.end, 0.0)
                for k, phase in enumerate(self.phases)
                if phase.action is not None and self.is_geometric(k)]

    def is_geometric(self, k: int) -> bool:
        """By the action's mode when known; otherwise by its effect on the world."""
        phase = self.phases[k]
        kind = self._kinds[k]
        if kind is not None:
            return kind.geometric
        if phase.start < phase.end or self._closed_before[k] != self._closed_after[k]:
            return True
        return any(not np.allclose(poses[k], poses[k + 1], atol=1e-6)
                   for poses in self._boundary.values())

    def _state(self, t: float, q: np.ndarray, k: int, after: bool) -> FrameState:
        """The state at configuration q in phase k; `after`: once the phase's mode
        switch has happened (its end boundary)."""
        n = len(self.phases)
        if k < 0:
            closed = self._closed_before[0] if n else False
            return FrameState(t, tuple(q), self._resting(0), closed, "start", 0, self.steps)
        if k >= n:
            label = "done" if self.solution.solved else f"stopped ({self.solution.status})"
            closed = self._closed_after[-1] if n else False
            return FrameState(t, tuple(q), self._resting(n), closed, label, self.steps,
                              self.steps)
        phase = self.phases[k]
        if after:
            poses, closed = self._resting(k + 1), self._closed_after[k]
        else:
            poses, closed = self._resting(k), self._closed_before[k]
            if k in self._grasp:
                poses[phase.attached] = self._tool_pose(q) @ self._grasp[k]
        # Held in a grasp (fingers closed), as opposed to pushed along; a symbolic
        # action (no mode switch) still holds it at its end (blind6 p04: a widget let
        # go of during a `scan`, 1 cm over the scanner, fell in the physics replay).
        kind = self._kinds[k]
        holds = (kind is not None and not kind.geometric) if after else \
            (kind is None or kind.holds)
        held = phase.attached if phase.attached is not None and self._closed_before[k] and \
            holds else None
        return FrameState(t, tuple(q), poses, closed, phase_label(phase), self._step[k],
                          self.steps, held)

    def _resting(self, boundary: int) -> dict:
        return {name: poses[min(boundary, len(poses) - 1)].copy()
                for name, poses in self._boundary.items()}
