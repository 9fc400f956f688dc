"""The caption bar drawn on every frame (Pillow): action, step i/n, problem."""

from __future__ import annotations

import numpy as np
from PIL import Image, ImageDraw, ImageFont

# Looked up on the system font path by Pillow; the bitmap default otherwise.
_TRUETYPE = ("DejaVuSans.ttf", "LiberationSans-Regular.ttf", "Arial.ttf")


def load_font(size: int, names: tuple[str, ...] = _TRUETYPE):
    for name in names:
        try:
            return ImageFont.truetype(name, size)
        except OSError:
            continue
    try:
        return ImageFont.load_default(size)
    except TypeError:  # Pillow < 10.1: the fixed-size bitmap font only
        return ImageFont.load_default()


def caption_text(label: str, step: int, steps: int, problem: str) -> tuple[str, str]:
    """Left and right parts of the bar."""
    return label, f"step {step}/{steps}   {problem}" if problem else f"step {step}/{steps}"


class Captioner:
    """Draws captions at one frame size; keeps its font (loading one is slow)."""

    def __init__(self, width: int, height: int):
        self.width, self.height = width, height
        self.size = self.font_size(height)
        self.font = load_font(self.size)
        self.pad = max(3, self.size // 3)
        self.bar = self.bar_height(height)

    @staticmethod
    def font_size(height: int) -> int:
        return max(10, round(height / 28))

    @classmethod
    def bar_height(cls, height: int) -> int:
        """Pixels the bar takes at the bottom of a frame `height` pixels tall."""
        size = cls.font_size(height)
        return size + 2 * max(3, size // 3)

    def draw(self, frame: np.ndarray, left: str, right: str) -> np.ndarray:
        image = Image.fromarray(frame)
        band = image.crop((0, self.height - self.bar, self.width, self.height))
        band = Image.blend(band, Image.new("RGB", band.size, (20, 20, 24)), 0.7)
        image.paste(band, (0, self.height - self.bar))
        draw = ImageDraw.Draw(image)
        y = self.height - self.bar + self.pad
        right_width = draw.textlength(right, font=self.font)
        room = self.width - right_width - 4 * self.pad
        draw.text((self.width - self.pad - right_width, y), right, font=self.font,
                  fill=(200, 200, 205))
        draw.text((self.pad, y), self._fit(draw, left, room), font=self.font,
                  fill=(255, 255, 255))
        return np.asarray(image)

    def _fit(self, draw: ImageDraw.ImageDraw, text: str, room: float) -> str:
        if draw.textlength(text, font=self.font) <= room:
            return text
        while text and draw.textlength(text + "…", font=self.font) > room:
            text = text[:-1]
        return text + "…" if text else ""
