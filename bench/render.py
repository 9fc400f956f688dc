"""Render speed: 300 frames at 640x480 to mp4, with 1 and 2 worker processes.

The peer is the bare renderer: the same states posed and photographed with
PyBullet's TinyRenderer in one process, no captions, no encoding. The ratios
to it show what the pipeline costs (1 worker) and what parallelism buys
(2 workers). Wall time depends on what else the shared machine runs, so CPU
time (this process and its children: workers, ffmpeg) is reported as well.
Run: .venv/bin/python bench/render.py [--quick]; writes bench/results/render.md.
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import sys
import tempfile
import time
from pathlib import Path

import imageio.v3 as iio

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests" / "render"))

from render_solutions import panda_solution  # noqa: E402

from tampcli.geometry.world import World  # noqa: E402
from tampcli.render.frames import FrameJob, _runs, frame_renderer  # noqa: E402
from tampcli.render.inputs import load_inputs  # noqa: E402
from tampcli.render.options import RenderOptions  # noqa: E402
from tampcli.render.video import _plan, render_solution  # noqa: E402

OUT = ROOT / "bench" / "results" / "render.md"
WIDTH, HEIGHT, FPS, PAUSE = 640, 480, 30.0, 0.4


def options_for(frames: int, workers: int) -> RenderOptions:
    # start, pick, place and end pauses + motion = (frames - 1) / fps seconds
    motion = (frames - 1) / FPS - 4 * PAUSE
    return RenderOptions(width=WIDTH, height=HEIGHT, fps=FPS, pause=PAUSE, duration=motion,
                         workers=workers)


def planned(inputs, options: RenderOptions):
    """The replay and camera `render_solution` would use."""
    with World(inputs.scene) as world:
        return _plan(inputs, world, options)


def cpu_seconds() -> float:
    """CPU time of this process and of its finished children (workers, ffmpeg)."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime


def peer(solution, frames: int) -> tuple[float, float]:
    """(wall, CPU) seconds to pose and photograph every state in this process."""
    options = options_for(frames, 1)
    inputs = load_inputs(solution)
    replay, camera = planned(inputs, options)
    states = replay.states(FPS)
    assert len(states) == frames, len(states)
    job = FrameJob(inputs.scene, camera, WIDTH, HEIGHT, caption=False)
    with frame_renderer(job) as renderer:
        world = renderer.world
        start, cpu = time.perf_counter(), cpu_seconds()
        for state in states:
            world.set_state(state.q, state.poses, fingers_closed=state.fingers_closed)
            world.camera_image(WIDTH, HEIGHT, camera.eye, camera.target, camera.up, camera.fov)
        return time.perf_counter() - start, cpu_seconds() - cpu


def ours(solution, frames: int, workers: int, folder: Path) -> tuple[float, float]:
    out = folder / f"w{workers}.mp4"
    start, cpu = time.perf_counter(), cpu_seconds()
    report = render_solution(solution, out, options_for(frames, workers))
    seconds, cpu = time.perf_counter() - start, cpu_seconds() - cpu
    assert report["frames"] == frames == len(iio.imread(out, index=None)), report
    return seconds, cpu


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true", help="60 frames instead of 300")
    args = parser.parse_args()
    frames = 60 if args.quick else 300
    solution = panda_solution()
    rows = []
    loads = [os.getloadavg()[0]]
    rows.append(("bare renderer (peer): pose + TinyRenderer, 1 process",
                 *peer(solution, frames)))
    loads.append(os.getloadavg()[0])
    with tempfile.TemporaryDirectory() as folder:
        for workers in (1, 2):
            rows.append((f"`render_solution` to mp4, {workers} worker"
                         f"{'s' if workers > 1 else ''}", *ours(solution, frames, workers,
                                                              Path(folder))))
            loads.append(os.getloadavg()[0])
    unique = len(_runs(planned(load_inputs(solution), options_for(frames, 1))[0].states(FPS))[0])
    t_peer = rows[0][1]
    lines = [
        "# Render benchmark",
        "",
        f"`bench/render.py{' --quick' if args.quick else ''}` on {platform.machine()}, "
        f"{os.cpu_count()} cores, load average (1 min) "
        f"{' -> '.join(f'{v:.1f}' for v in loads)} over the runs "
        "(the machine is shared with other engineers' jobs: wall times are inflated by "
        "that; CPU times are not).",
        f"Panda pick-and-place solution (tests/render), {frames} frames at {WIDTH}x{HEIGHT}, "
        f"{FPS:g} fps ({unique} distinct: pauses are rendered once); "
        "target: 300 frames in <= 30 s on 2 cores.",
        "`render_solution` = load + check + frames + captions + H.264 encoding; its CPU "
        "includes the worker processes (start-up: imports and a World each) and ffmpeg.",
        "",
        "| run | wall (s) | frames/s | wall / peer | CPU (s) | CPU ms/frame |",
        "| --- | ---: | ---: | ---: | ---: | ---: |",
    ]
    for name, seconds, cpu in rows:
        lines.append(f"| {name} | {seconds:.1f} | {frames / seconds:.1f} | "
                     f"{seconds / t_peer:.2f} | {cpu:.1f} | {1000 * cpu / frames:.0f} |")
    speedup = rows[1][1] / rows[2][1]
    cpu2 = rows[2][2]
    lines += ["", f"2 workers vs 1 (wall): {speedup:.2f}x. On 2 idle cores the 2-worker run "
              f"needs about {cpu2 / 2:.1f} s (its CPU time / 2).", ""]
    OUT.write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
