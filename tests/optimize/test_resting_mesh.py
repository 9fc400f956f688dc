"""A mesh rests 1 mm into its support by the collision model (its hull grown by
PyBullet's 1 mm margin, as getClosestPoints measures it): the carry that lifts it off
(or sets it down) may start (end) that deep in what it leaves (enters), no deeper
(verify.failing_motions). blind30 p06, written blind: every pick of a mesh part
failed `collision part vs bench: -0.1 cm at waypoint 10.0`, and the problem ended
`limit` after every skeleton."""

from __future__ import annotations

from pathlib import Path

from tampcli.optimize import verify

from .helpers import lowered_folder, ops, path_from_keyframes

SCANNER = Path(__file__).resolve().parents[2] / "problems" / "blind30" / "p06"
PLAN = ("(pick part intake)", "(scan part scanner)", "(place part bin)", "(report part bin)")


def test_a_mesh_lifted_off_its_support_is_not_a_collision():
    with lowered_folder(SCANNER, "p06", ops(*PLAN)) as problem:
        path = path_from_keyframes(problem)
        assert path.solved, path.worst_constraint
        assert verify.verify(problem, path, fingers=path.fingers) == []


def test_only_the_depth_at_the_keyframe_is_allowed():
    """The allowance is for the held object's contacts deeper than the tolerance at the
    end keyframe and no deeper than RESTING_DEPTH; nothing else is let through."""
    from types import SimpleNamespace as C

    found = [C(a="held:part", b="body:bench", distance=-0.0012),
             C(a="held:part", b="body:wall", distance=-0.0012),
             C(a="link:hand", b="body:bench", distance=-0.0015),
             C(a="held:part", b="body:bench2", distance=-0.004)]
    depths = verify._depths(found, frozenset({"bench", "bench2"}))
    assert depths == {("held:part", "body:bench"): -0.0012}
