"""Helpers for the map_server unit tests: make the package importable, write test maps."""

import sys
from pathlib import Path

import numpy as np

PKG_SRC = Path(__file__).resolve().parent.parent / "src"
if str(PKG_SRC) not in sys.path:
    sys.path.insert(0, str(PKG_SRC))


def write_pgm_p5(path, pixels):
    pixels = np.asarray(pixels, dtype=np.uint8)
    h, w = pixels.shape
    Path(path).write_bytes(f"P5\n{w} {h}\n255\n".encode() + pixels.tobytes())
    return Path(path)


def write_yaml(
    path,
    image,
    resolution=0.05,
    origin="[0.0, 0.0, 0.0]",
    negate=0,
    occupied=0.65,
    free=0.196,
    mode=None,
    extra="",
):
    text = (
        f"image: {image}\nresolution: {resolution}\norigin: {origin}\nnegate: {negate}\n"
        f"occupied_thresh: {occupied}\nfree_thresh: {free}\n"
    )
    if mode is not None:
        text += f"mode: {mode}\n"
    Path(path).write_text(text + extra)
    return Path(path)
