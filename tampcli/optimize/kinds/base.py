"""The interface of a mode kind: what an action of that kind is, through every stage.

Each method gets the walk of one stage (an object of the stage's module that
holds what is held and what rests where at this point of the skeleton, and
the helpers every kind uses) and the step, and adds that step's part; the
stages themselves only loop over the steps.
"""

from __future__ import annotations

from abc import ABC, abstractmethod


class ModeKind(ABC):
    """One `mode = "..."` of modes.toml. Subclasses set the class attributes and
    implement every method; kinds/__init__.py registers one instance each."""

    name: str  # the modes.toml value
    required: tuple[str, ...] = ()  # roles (object, on, to) modes.toml must give
    optional: tuple[str, ...] = ()  # roles it may give
    geometric: bool = True  # moves something: motion phases, a panel in the keyframe strip
    places: bool = False  # leaves its object resting somewhere new: a block of the final NLP
    holds: bool = True  # replay: what is attached during its motions hangs in closed fingers
    fingers: bool | None = None  # replay: the fingers are closed after it (None: unchanged)
    planar_grip: bool = False  # `grip` also says how the planar robot holds (a push's face)
    # The planar robot moves the object only within the friction cone of one of its
    # faces, without turning it (a push): what optimize/push_reach.py proves things of.
    within_cone: bool = False

    def __repr__(self) -> str:
        return self.name

    @abstractmethod
    def lower(self, lo, index: int, op, mode):
        """The step of action `op` (skeleton.Step); add its motion phases to `lo`
        (skeleton.Lowering), or raise skeleton.LoweringError."""

    @abstractmethod
    def grip(self, problem, step, choice):
        """How the arm holds the step's object (grips.Grip); `choice` a values.GripChoice.
        The planar robot's grip is one for every kind (world_state.grip_of) unless
        the kind sets `planar_grip`."""

    @abstractmethod
    def final_rows(self, walk, step) -> None:
        """Rows of the "final" NLP (placements only; stages.FinalWalk)."""

    @abstractmethod
    def guess(self, walk, step) -> None:
        """Initial configurations of the step's keyframes (init.GuessWalk), forwards."""

    @abstractmethod
    def reseed(self, walk, step, k: int) -> None:
        """Revise the guess of keyframe k of this step, walking backwards (arm only)."""

    @abstractmethod
    def keyframe_rows(self, walk, step) -> None:
        """Rows of the "keyframes" NLP (stages.KeyframeWalk)."""

    @abstractmethod
    def switch(self, walk, step) -> None:
        """The mode switch at the end of the step, in numbers (assemble.MotionWalk)."""

    @abstractmethod
    def phases(self, walk, step) -> None:
        """The step's mode switch in the trajectory's phases (assemble.PhaseWalk)."""

    def relax(self, builder, step) -> None:
        """The step's rows in the planar robot's convex relaxation (relaxed.Builder:
        its linear ones). By default none, which only lowers the bound, and where
        the step's object ends up is unknown from here on."""
        builder.forget(step)

    def relax_faces(self, problem, step) -> tuple[float, ...]:
        """The discrete choices (faces) the relaxation takes one QP each; none by default."""
        return ()

    def path_rows(self, rows, label, problem, qs, held, kin) -> None:  # noqa: B027 (optional)
        """Rows the kind adds to the path NLP of its own motion (`MotionPhase.own`)
        through configurations qs; none by default."""

    @abstractmethod
    def check(self, walk, step) -> list[str]:
        """What `verify` re-measures of the step in a trajectory (verify.StepCheck)."""
