"""Render speed: 300 frames at 640x480 to mp4, with 1 and 2 worker processes.

The peer is the bare renderer: the same states posed and photographed with
PyBullet's TinyRenderer in one process, no captions, no encoding. The ratios
to it show what the pipeline costs (1 worker) and what parallelism buys
(2 workers) on this machine, whatever else it is running.
Run: .venv/bin/python bench/render.py [--quick]; writes bench/results/render.md.
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import tempfile
import time
from pathlib import Path

import imageio.v3 as iio

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests" / "render"))

from render_solutions import panda_solution  # noqa: E402

from tampcli.render.frames import FrameJob, frame_renderer  # noqa: E402
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


def peer(solution, frames: int) -> float:
    """Seconds to pose and photograph every state in this process, nothing else."""
    options = options_for(frames, 1)
    inputs = load_inputs(solution)
    replay, camera = _plan(inputs, options)
    states = replay.states(FPS)
    assert len(states) == frames, len(states)
    job = FrameJob(inputs.scene, camera, WIDTH, HEIGHT, caption=False)
    with frame_renderer(job) as renderer:
        world = renderer.world
        start = time.perf_counter()
        for state in states:
            world.set_state(state.q, state.poses, fingers_closed=state.fingers_closed)
            world.camera_image(WIDTH, HEIGHT, camera.eye, camera.target, camera.up, camera.fov)
        return time.perf_counter() - start


def ours(solution, frames: int, workers: int, folder: Path) -> tuple[float, int]:
    out = folder / f"w{workers}.mp4"
    start = time.perf_counter()
    report = render_solution(solution, out, options_for(frames, workers))
    seconds = time.perf_counter() - start
    assert report["frames"] == frames == len(iio.imread(out, index=None)), report
    return seconds, report["frames"]


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true", help="60 frames instead of 300")
    args = parser.parse_args()
    frames = 60 if args.quick else 300
    solution = panda_solution()
    rows = []
    loads = [os.getloadavg()[0]]
    t_peer = peer(solution, frames)
    loads.append(os.getloadavg()[0])
    rows.append(("bare renderer (peer): pose + TinyRenderer, 1 process", t_peer))
    with tempfile.TemporaryDirectory() as folder:
        for workers in (1, 2):
            seconds, _ = ours(solution, frames, workers, Path(folder))
            loads.append(os.getloadavg()[0])
            rows.append((f"`render_solution` to mp4, {workers} worker"
                         f"{'s' if workers > 1 else ''} (load + frames + captions + H.264)",
                         seconds))
    lines = [
        "# Render benchmark",
        "",
        f"`bench/render.py{' --quick' if args.quick else ''}` on {platform.machine()}, "
        f"{os.cpu_count()} cores, load average (1 min) "
        f"{' -> '.join(f'{v:.1f}' for v in loads)} over the runs "
        "(the machine is shared with other engineers' jobs: read the ratios).",
        f"Panda pick-and-place solution (tests/render), {frames} frames at {WIDTH}x{HEIGHT}, "
        f"{FPS:g} fps; target: 300 frames in <= 30 s on 2 cores.",
        "",
        "| run | wall (s) | frames/s | ms/frame | / peer |",
        "| --- | ---: | ---: | ---: | ---: |",
    ]
    for name, seconds in rows:
        lines.append(f"| {name} | {seconds:.1f} | {frames / seconds:.1f} | "
                     f"{1000 * seconds / frames:.0f} | {seconds / t_peer:.2f} |")
    speedup = rows[1][1] / rows[2][1]
    lines += ["", f"2 workers vs 1: {speedup:.2f}x faster.", ""]
    OUT.write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
