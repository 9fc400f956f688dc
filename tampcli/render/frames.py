"""Frames: a World posed per FrameState, photographed by TinyRenderer, captioned.

Rendering is CPU-bound (~0.1 s a frame at 640x480), so frames are spread over
worker processes, each with its own World (a PyBullet client belongs to one
process). Chunk c of the frames goes to worker c % W and every worker has its
own bounded queue, so the parent reads chunks strictly in order from the
worker that owns the next one: frames come out in order and at most a few
chunks per worker wait in memory.
"""

from __future__ import annotations

import multiprocessing
import queue as queue_module
import traceback
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from tampcli.render.camera import Camera
from tampcli.render.captions import Captioner, caption_text
from tampcli.render.replay import FrameState
from tampcli.render.scenery import add_regions

CHUNK = 4  # frames per message: large enough to amortize pickling, small for memory
QUEUE_DEPTH = 3  # chunks a worker may run ahead of the encoder
_POLL_SECONDS = 1.0


@dataclass(frozen=True)
class FrameJob:
    """What every renderer needs; picklable, so workers can rebuild their World."""

    scene: object  # geometry.scene.Scene
    camera: Camera
    width: int
    height: int
    problem: str = ""
    caption: bool = True


class FrameRenderer:
    """Renders FrameStates with one World (which it borrows, not owns)."""

    def __init__(self, world, job: FrameJob):
        self.world, self.job = world, job
        self.captioner = Captioner(job.width, job.height) if job.caption else None

    def render(self, state: FrameState) -> np.ndarray:
        self.world.set_state(np.asarray(state.q), state.poses,
                             fingers_closed=state.fingers_closed, fingers=state.fingers)
        cam = self.job.camera
        image = self.world.camera_image(self.job.width, self.job.height, cam.eye, cam.target,
                                        up=cam.up, fov=cam.fov)
        image = np.ascontiguousarray(image[:, :, :3], dtype=np.uint8)
        if self.captioner is not None:
            image = self.captioner.draw(image, *caption_text(state.label, state.step,
                                                             state.steps, self.job.problem))
        return image


@contextmanager
def frame_renderer(job: FrameJob, world=None):
    """A FrameRenderer on `world` (the caller's open World of `job.scene`, its
    regions already drawn: see `scenery.add_regions`), or, where that World has no
    visual shapes to draw (World's `visuals`), on a World of its own."""
    if world is not None and world.visuals:
        yield FrameRenderer(world, job)
        return
    from tampcli.geometry.world import World

    with World(job.scene) as own:
        add_regions(own)
        yield FrameRenderer(own, job)


def render_frames(job: FrameJob, states: Sequence[FrameState], workers: int = 1,
                  on_frame: Callable[[], None] | None = None,
                  world=None) -> Iterator[np.ndarray]:
    """The frames of `states`, in order, rendered by `workers` processes.

    A run of identical states (a pause) is rendered once and repeated. This
    process renders on `world` when given (see `frame_renderer`); each worker
    process builds its own (a PyBullet client belongs to one process).
    """
    unique, repeats = _runs(states)
    workers = workers_used(len(unique), workers)
    if workers == 1:
        frames = _render_here(job, unique, world)
    else:
        frames = _render_in_workers(job, unique, workers, world)
    try:
        for frame, count in zip(frames, repeats, strict=True):
            for _ in range(count):
                if on_frame:
                    on_frame()
                yield frame
    finally:
        frames.close()  # stops the workers now, also when the consumer gave up early


def workers_used(distinct: int, workers: int) -> int:
    """No more workers than chunks of distinct frames."""
    return max(1, min(workers, -(-distinct // CHUNK)))


def distinct_count(states: Sequence[FrameState]) -> int:
    return len(_runs(states)[0])


def _runs(states: Sequence[FrameState]) -> tuple[list[FrameState], list[int]]:
    unique: list[FrameState] = []
    repeats: list[int] = []
    last = None
    for state in states:
        key = _key(state)
        if key == last:
            repeats[-1] += 1
        else:
            unique.append(state)
            repeats.append(1)
            last = key
    return unique, repeats


def _key(state: FrameState) -> tuple:
    poses = tuple((name, np.asarray(pose).tobytes()) for name, pose in sorted(state.poses.items()))
    return state.q, poses, state.fingers_closed, state.label, state.step, state.steps


def _render_here(job, states, world):
    with frame_renderer(job, world) as renderer:
        for state in states:
            yield renderer.render(state)


def _render_in_workers(job, states, workers, world):
    """Slot 0 is this process (one start-up fewer); slots 1.. are spawned."""
    chunks = [list(states[i:i + CHUNK]) for i in range(0, len(states), CHUNK)]
    # spawn, not fork: the parent may hold a PyBullet client and a progress thread.
    ctx = multiprocessing.get_context("spawn")
    queues = {w: ctx.Queue(maxsize=QUEUE_DEPTH) for w in range(1, workers)}
    processes = {
        w: ctx.Process(target=_worker, args=(job, chunks[w::workers], queues[w]), daemon=True,
                       name=f"tampcli-render-{w}")
        for w in range(1, workers)}
    try:
        for process in processes.values():
            process.start()
        with frame_renderer(job, world) as renderer:
            for c, chunk in enumerate(chunks):
                w = c % workers
                if w == 0:
                    yield from (renderer.render(state) for state in chunk)
                else:
                    yield from _receive(queues[w], processes[w])
        for process in processes.values():
            process.join(timeout=10)
    finally:
        for process in processes.values():
            if process.is_alive():
                process.terminate()
            process.join(timeout=5)
        for q in queues.values():
            q.close()
            q.cancel_join_thread()


def _receive(q, process) -> list[np.ndarray]:
    while True:
        try:
            kind, payload = q.get(timeout=_POLL_SECONDS)
        except queue_module.Empty:
            if not process.is_alive():
                raise RuntimeError(f"render worker {process.name} died "
                                   f"(exit code {process.exitcode})") from None
            continue
        if kind == "error":
            raise RuntimeError(f"render worker {process.name} failed:\n{payload}")
        return payload


def _worker(job: FrameJob, chunks: list[list[FrameState]], q) -> None:
    try:
        with frame_renderer(job) as renderer:
            for chunk in chunks:
                q.put(("frames", [renderer.render(state) for state in chunk]))
    except BaseException:  # reported to the parent, which raises it there
        q.put(("error", traceback.format_exc()))
