"""`render_solution`: a solution.json (or Solution, or the inputs a solve already
holds) -> mp4 / gif, keyframe strip, and optionally a physics check. `solve
--video` and `tampcli render` call it."""

from __future__ import annotations

import time
from contextlib import contextmanager
from pathlib import Path

from tampcli.render.camera import choose_camera
from tampcli.render.captions import Captioner
from tampcli.render.encode import keyframe_strip, open_writer, save_image
from tampcli.render.frames import (
    FrameJob,
    distinct_count,
    frame_renderer,
    render_frames,
    workers_used,
)
from tampcli.render.inputs import RenderInputs, check_against_world, load_inputs, mode_kind_of
from tampcli.render.options import RenderOptions, check_writable, image_format, video_format
from tampcli.render.progress import progress
from tampcli.render.replay import Replay
from tampcli.render.scenery import add_regions, visible_points
from tampcli.solution import Solution
from tampcli.solution_fit import finger_rows


def render_solution(source: RenderInputs | Solution | str | Path,
                    out_path: str | Path | None, options: RenderOptions | None = None,
                    ui=None, keyframes: str | Path | None = None, world=None) -> dict:
    """Replay `source` into `out_path` (.mp4 or .gif) and/or a keyframe strip.

    `source` is a solution file or value (its scene and modes are then read
    here), or RenderInputs a caller already holds. `world`, when given, is the
    caller's open World of that scene: rendering borrows it (adding the goal
    regions' plates) instead of building one; a physics replay always builds
    its own, since it changes the world's dynamics.

    Returns what was made: `path`, `frames`, `seconds` (video length),
    `width`, `height`, `fps`, `render_seconds` (wall time), and `keyframes`,
    `panels`, `physics` when asked. Bad paths and a solution that does not fit
    its scene raise InputError before any frame is rendered.
    """
    options = options or RenderOptions()
    kind = video_format(out_path, options.width, options.height) if out_path else None
    if keyframes is not None:
        image_format(keyframes)
    for path, key in ((out_path, "--video"), (keyframes, "--keyframes")):
        if path is not None:
            check_writable(path, key)
    started = time.perf_counter()
    inputs = source if isinstance(source, RenderInputs) else load_inputs(source)
    with _borrowed_or_own(inputs.scene, world) as world:
        replay, camera = _plan(inputs, world, options)
        add_regions(world)
        job = FrameJob(inputs.scene, camera, options.width, options.height,
                       inputs.problem_name, options.caption)
        report: dict = {"path": str(out_path) if out_path else None, "frames": 0,
                        "seconds": round(float(replay.duration), 3), "width": options.width,
                        "height": options.height, "fps": options.fps,
                        "camera": {"eye": camera.eye, "target": camera.target,
                                   "fov": camera.fov}}
        if kind is not None:
            states = replay.states(options.fps)
            report["frames"] = _write_video(kind, out_path, job, states, options, ui, world)
            report["distinct_frames"] = distinct_count(states)
            report["workers"] = workers_used(report["distinct_frames"], options.worker_count)
        if keyframes is not None:
            report["keyframes"], report["panels"] = str(keyframes), _write_strip(
                keyframes, job, replay, world)
    if options.physics:
        from tampcli.render.physics import replay_physics

        report["physics"] = replay_physics(inputs, mode_kind_of(inputs.modes),
                                           options.speed).as_json()
    report["render_seconds"] = round(time.perf_counter() - started, 3)
    return report


@contextmanager
def _borrowed_or_own(scene, world):
    """The caller's World where it can draw (it was loaded with its visual shapes), or
    one of the video's own."""
    if world is not None and world.visuals:
        yield world
        return
    from tampcli.geometry.world import World

    with World(scene) as own:
        yield own


def _plan(inputs, world, options: RenderOptions):
    """Check the solution against the World, then time it and place the camera."""
    check_against_world(inputs, world)
    replay = Replay(inputs.solution, world.tool_pose, mode_kind=mode_kind_of(inputs.modes),
                    duration=options.duration, speed=options.speed, pause=options.pause,
                    fingers=None if inputs.file is None else finger_rows(inputs.file, world))
    points = None
    if inputs.scene.camera is None:
        points = visible_points(world, replay.states(min(options.fps, 4.0)))
    bar = Captioner.bar_height(options.height) / options.height if options.caption else 0.0
    camera = choose_camera(options.camera, inputs.scene.camera, points,
                           options.width / options.height, reserve_bottom=bar)
    return replay, camera


def _write_video(kind, out_path, job, states, options, ui, world) -> int:
    writer = open_writer(kind, out_path, options.fps, options.width, options.height)
    try:
        with progress(ui, len(states), f"rendering {Path(out_path).name}") as advance:
            for frame in render_frames(job, states, options.worker_count, advance, world):
                writer.append(frame)
        writer.close()
    except BaseException:
        _discard(writer, out_path)
        raise
    return writer.frames


def _discard(writer, out_path) -> None:
    """A half-written video is worse than none."""
    try:
        writer.close()
    except Exception:  # noqa: BLE001 - already failing; the first error is the one to show
        pass
    Path(out_path).unlink(missing_ok=True)


def _write_strip(path, job, replay, world) -> int:
    states = replay.keyframes()
    if not states:  # no geometric action: show where the robot starts and ends
        states = [replay.state_at(0.0), replay.state_at(replay.duration)]
    with frame_renderer(job, world) as renderer:
        panels = [renderer.render(state) for state in states]
    save_image(keyframe_strip(panels), path)
    return len(panels)
