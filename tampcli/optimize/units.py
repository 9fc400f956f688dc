"""Lengths in messages, as precisely as they differ."""

from __future__ import annotations


def cm(metres: float) -> str:
    """`metres` in cm with one decimal, or as many more (up to three) as it has: an
    edge a millimetre's fraction off reads so (blind35 DOC_GAPS 1: a case 8.195 cm
    wide refused as "8.2 cm wide; ... takes at most 8.2 cm", the limit 8.19)."""
    text = f"{100 * metres:.3f}".rstrip("0")
    return text + "0" if text.endswith(".") else text
