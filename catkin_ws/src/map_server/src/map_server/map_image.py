"""Map images: read any supported image as grey values, and the pixel <-> cell rules."""

import io
from pathlib import Path

import numpy as np
from rosbook_env.files import looked_in_note, special_file_note

from map_server import pgm
from map_server.errors import MapFileNotFoundError, MapImageError

# map_saver's pixel values.
PGM_FREE, PGM_OCCUPIED, PGM_UNKNOWN = 254, 0, 205
DEFAULT_SAVE_OCCUPIED, DEFAULT_SAVE_FREE = 65, 0


def read_grey_image(path):
    """Load an image as grey values 0..255 (float, row 0 at the top).

    Returns (grey, opaque): opaque is a bool array (False where alpha is 0) or None
    when the image has no alpha channel. Colour channels are averaged; 16-bit images
    are scaled to 0..255.
    """
    path = Path(path)
    special = special_file_note(path)
    if special:
        raise MapImageError(f"{path}: {special}; give the map image file")
    try:
        with open(path, "rb") as handle:
            data = handle.read()
    except FileNotFoundError:
        raise MapFileNotFoundError(f"{path}: map image not found{looked_in_note(path)}") from None
    except OSError as err:
        raise MapImageError(f"{path}: cannot read image: {err.strerror or err}") from None
    if pgm.is_pgm(data):
        try:
            pixels, maxval = pgm.parse_pgm(data)
        except pgm.PgmError as err:
            raise MapImageError(f"{path}: corrupt PGM image: {err}") from None
        return pixels.astype(np.float64) * (255.0 / maxval), None
    return _read_with_pil(path, data)


def _read_with_pil(path, data):
    from PIL import Image, UnidentifiedImageError

    try:
        image = Image.open(io.BytesIO(data))
        image.load()
    except Image.DecompressionBombError as err:  # a small file declaring a huge picture
        raise MapImageError(f"{path}: too large for a map: {err}") from None
    except UnidentifiedImageError:
        raise MapImageError(
            f"{path}: not an image format this map server reads (PGM, PNG, JPG, ...)"
        ) from None
    except (OSError, ValueError, SyntaxError) as err:
        raise MapImageError(f"{path}: corrupt or truncated image: {err}") from None
    mode = image.mode
    if mode in ("I;16", "I;16B", "I;16L", "I"):
        pixels = np.asarray(image, dtype=np.float64)
        if pixels.size and (pixels.max() > 65535 or pixels.min() < 0):
            raise MapImageError(f"{path}: {mode} image values exceed 16 bits; not supported")
        return pixels * (255.0 / 65535.0), None
    if mode == "F":
        raise MapImageError(f"{path}: floating-point images are not supported")
    if mode == "P":
        image = image.convert("RGBA" if "transparency" in image.info else "RGB")
    elif mode in ("1", "L"):
        image = image.convert("L")
    elif mode not in ("LA", "RGB", "RGBA"):
        image = image.convert("RGBA" if "A" in mode else "RGB")
    pixels = np.asarray(image, dtype=np.float64)
    if pixels.ndim == 2:
        return pixels, None
    has_alpha = image.mode in ("LA", "RGBA")
    colour = pixels[:, :, :-1] if has_alpha else pixels
    grey = colour.mean(axis=2)
    opaque = pixels[:, :, -1] > 0 if has_alpha else None
    return grey, opaque


def grey_to_occupancy(grey, opaque, negate, occupied_thresh, free_thresh, mode):
    """map_server's rule, cell by cell; returns int8 cells in image order (top row first)."""
    grey = np.asarray(grey, dtype=np.float64)
    if negate:
        grey = 255.0 - grey
    if mode == "raw":
        # The original stores the byte as-is in an int8 cell: 255 reads back as -1.
        return np.trunc(np.clip(grey, 0, 255)).astype(np.uint8).view(np.int8)
    occ = (255.0 - grey) / 255.0
    cells = np.full(grey.shape, -1, dtype=np.int8)
    if mode == "scale":
        ratio = (occ - free_thresh) / (occupied_thresh - free_thresh)
        scaled = np.trunc(1.0 + 98.0 * np.clip(ratio, 0.0, 1.0)).astype(np.int8)
        between = (occ <= occupied_thresh) & (occ >= free_thresh)
        if opaque is not None:
            between &= opaque
        cells[between] = scaled[between]
    cells[occ > occupied_thresh] = 100
    cells[occ < free_thresh] = 0
    if opaque is not None:
        cells[~opaque] = -1  # a transparent pixel says nothing about the world
    return cells


def occupancy_to_pgm(data, occupied=DEFAULT_SAVE_OCCUPIED, free=DEFAULT_SAVE_FREE):
    """map_saver's rule: 0..free -> 254, >= occupied -> 0, else 205; returns top row first."""
    values = np.asarray(data).astype(np.int16)
    pixels = np.full(values.shape, PGM_UNKNOWN, dtype=np.uint8)
    pixels[(values >= 0) & (values <= free)] = PGM_FREE
    pixels[values >= occupied] = PGM_OCCUPIED
    return pixels[::-1].copy()
