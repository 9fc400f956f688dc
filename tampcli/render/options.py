"""Render options: one frozen value, validated when built."""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path

from tampcli.errors import UsageError

VIDEO_FORMATS = {".mp4": "mp4", ".gif": "gif"}
IMAGE_FORMATS = (".png", ".jpg", ".jpeg")


@dataclass(frozen=True)
class RenderOptions:
    """How to replay and encode.

    width, height: pixels of each frame (mp4 needs both even: H.264 in yuv420p).
    fps: frames per second of the video.
    camera: `--camera` fields (eye, target, up, fov) over the scene's `[camera]`
        and automatic framing; None = scene or automatic.
    workers: render processes; 0 = one per core.
    duration: seconds of robot motion (pauses excluded); None = from `speed`.
    speed: joint-space speed (rad/s, or m/s for the planar robot); None = a
        default per robot model, clamped so a video lasts 1..30 s of motion.
    pause: seconds held at each instantaneous action (grasp, place, ...) and
        at the start and the end.
    physics: also replay with PyBullet dynamics and report object drift.
    caption: draw the caption bar.
    """

    width: int = 640
    height: int = 480
    fps: float = 30.0
    camera: dict | None = None
    workers: int = 0
    duration: float | None = None
    speed: float | None = None
    pause: float = 0.4
    physics: bool = False
    caption: bool = True

    def __post_init__(self):
        for name in ("width", "height"):
            value = getattr(self, name)
            if not isinstance(value, int) or not 16 <= value <= 4096:
                raise UsageError(f"must be an integer in [16, 4096], got {value!r}",
                                 key=f"--{name}")
        if not (math.isfinite(self.fps) and 1.0 <= self.fps <= 120.0):
            raise UsageError(f"must be in [1, 120], got {self.fps}", key="--fps")
        if not isinstance(self.workers, int) or self.workers < 0:
            raise UsageError(f"must be a non-negative integer, got {self.workers!r}",
                             key="--workers")
        for name in ("duration", "speed"):
            value = getattr(self, name)
            if value is not None and not (math.isfinite(value) and value > 0):
                raise UsageError(f"must be a positive number, got {value}", key=f"--{name}")
        if not (math.isfinite(self.pause) and 0.0 <= self.pause <= 10.0):
            raise UsageError(f"must be in [0, 10] seconds, got {self.pause}", key="--pause")

    @property
    def worker_count(self) -> int:
        return self.workers or (os.cpu_count() or 1)


def video_format(path: str | Path, width: int, height: int) -> str:
    """"mp4" or "gif" from the extension; refuses anything else and odd mp4 sizes."""
    suffix = Path(path).suffix.lower()
    kind = VIDEO_FORMATS.get(suffix)
    if kind is None:
        raise UsageError(f"unknown video format {suffix or '(no extension)'!r}: "
                         f"use one of {', '.join(VIDEO_FORMATS)}", str(path), key="--video")
    if kind == "mp4" and (width % 2 or height % 2):
        raise UsageError(f"mp4 (H.264, yuv420p) needs an even width and height, got "
                         f"{width}x{height}", str(path), key="--video")
    return kind


def image_format(path: str | Path) -> str:
    suffix = Path(path).suffix.lower()
    if suffix not in IMAGE_FORMATS:
        raise UsageError(f"unknown image format {suffix or '(no extension)'!r}: "
                         f"use one of {', '.join(IMAGE_FORMATS)}", str(path), key="--keyframes")
    return suffix


def check_writable(path: str | Path, key: str) -> None:
    """Fail before rendering, not after a minute of it, when `path` cannot be written."""
    path = Path(path)
    existed = path.exists()
    if path.is_dir():
        raise UsageError("is a directory", str(path), key=key)
    try:
        with open(path, "ab"):
            pass
    except OSError as err:
        raise UsageError(f"cannot write: {err.strerror}", str(path), key=key) from None
    if not existed:
        path.unlink()
