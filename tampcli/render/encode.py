"""Encoders: mp4 (H.264 through imageio-ffmpeg), gif (Pillow), keyframe strips."""

from __future__ import annotations

import math
from pathlib import Path

import imageio.v2 as imageio
import numpy as np
from PIL import Image

from tampcli.errors import UsageError

STRIP_COLUMNS = 4  # panels per row of a keyframe strip
_GAP = 4  # pixels between panels


class Mp4Writer:
    """H.264 in yuv420p: plays everywhere; needs even frame sizes (checked by options)."""

    def __init__(self, path: str | Path, fps: float, width: int, height: int):
        self.path, self.size = str(path), (height, width)
        # macro_block_size=1: keep the size asked for (imageio would round it to 16).
        self._writer = imageio.get_writer(
            self.path, format="FFMPEG", mode="I", fps=fps, codec="libx264",
            pixelformat="yuv420p", macro_block_size=1, quality=7,
            ffmpeg_log_level="error",
            # veryfast: 40% less encoder CPU than the default preset, same size here
            output_params=["-preset", "veryfast", "-movflags", "+faststart"])
        self.frames = 0

    def append(self, frame: np.ndarray) -> None:
        self._writer.append_data(frame)
        self.frames += 1

    def close(self) -> None:
        self._writer.close()


class GifWriter:
    """Palette frames kept in memory (a third of RGB), written at close.

    One palette for the whole video, taken from the first frame (every body is
    in view from the start): per-frame palettes make flat surfaces flicker.

    GIF delays are in hundredths of a second, and viewers (and Pillow) merge
    identical consecutive frames, so a GIF read back may hold fewer frames than
    were appended; its total duration is preserved.
    """

    def __init__(self, path: str | Path, fps: float, width: int, height: int):
        self.path = str(path)
        self.delay_ms = max(20, int(round(100.0 / fps)) * 10)
        self._frames: list[Image.Image] = []
        self._palette: Image.Image | None = None
        self.frames = 0

    def append(self, frame: np.ndarray) -> None:
        image = Image.fromarray(frame)
        if self._palette is None:
            self._palette = image.quantize(colors=255, method=Image.Quantize.MEDIANCUT)
        # the first frame too goes through the palette lookup (which is coarser
        # than the palette itself), so no colour shifts after frame 0
        self._frames.append(image.quantize(palette=self._palette, dither=Image.Dither.NONE))
        self.frames += 1

    def close(self) -> None:
        if not self._frames:
            return
        first, rest = self._frames[0], self._frames[1:]
        try:
            first.save(self.path, format="GIF", save_all=True, append_images=rest,
                       duration=self.delay_ms, loop=0, optimize=False, disposal=1)
        except OSError as err:
            raise UsageError(f"cannot write: {err.strerror or err}", self.path,
                             key="--video") from None
        self._frames = []


WRITERS = {"mp4": Mp4Writer, "gif": GifWriter}


def open_writer(kind: str, path, fps: float, width: int, height: int):
    return WRITERS[kind](path, fps, width, height)


def keyframe_strip(panels: list[np.ndarray], columns: int = STRIP_COLUMNS) -> np.ndarray:
    """Panels side by side, wrapping after `columns`, on a white background."""
    if not panels:
        raise ValueError("a strip needs at least one panel")
    h, w = panels[0].shape[:2]
    columns = min(columns, len(panels))
    rows = math.ceil(len(panels) / columns)
    strip = np.full((rows * h + (rows - 1) * _GAP, columns * w + (columns - 1) * _GAP, 3), 255,
                    dtype=np.uint8)
    for i, panel in enumerate(panels):
        r, c = divmod(i, columns)
        strip[r * (h + _GAP):r * (h + _GAP) + h, c * (w + _GAP):c * (w + _GAP) + w] = panel
    return strip


def strip_geometry(count: int, width: int, height: int,
                   columns: int = STRIP_COLUMNS) -> tuple[int, int]:
    """(width, height) of a strip of `count` panels: what tests and users can expect."""
    columns = min(columns, count)
    rows = math.ceil(count / columns)
    return columns * width + (columns - 1) * _GAP, rows * height + (rows - 1) * _GAP


def save_image(image: np.ndarray, path: str | Path) -> None:
    try:
        Image.fromarray(image).save(str(path))
    except OSError as err:
        raise UsageError(f"cannot write: {err.strerror or err}", str(path),
                         key="--keyframes") from None
