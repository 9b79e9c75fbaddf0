"""Map files as map_server and map_saver use them, with no ROS dependency.

A map is a YAML file naming an image plus how to read it:

    image: map.pgm            # relative to the YAML file's folder (or absolute)
    resolution: 0.050000      # metres per cell
    origin: [x, y, yaw]       # pose of the lower-left cell in the map frame
    negate: 0                 # 1: white is occupied, black is free
    occupied_thresh: 0.65     # occupancy above this -> 100
    free_thresh: 0.196        # occupancy below this -> 0
    mode: trinary             # optional: trinary (default), scale or raw

A pixel's occupancy is (255 - v) / 255, or v / 255 with negate (v is the grey value,
colour averaged). Image row 0 is the top of the map; an OccupancyMap's row 0 is the
bottom, as in nav_msgs/OccupancyGrid.
"""

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import yaml

from map_server import pgm
from map_server.atomic import write_files_atomically

MODES = ("trinary", "scale", "raw")
REQUIRED_KEYS = ("image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh")
KNOWN_KEYS = frozenset(REQUIRED_KEYS + ("mode",))

# map_saver's pixel values and the thresholds its YAML declares.
PGM_FREE, PGM_OCCUPIED, PGM_UNKNOWN = 254, 0, 205
SAVED_OCCUPIED_THRESH, SAVED_FREE_THRESH = 0.65, 0.196
DEFAULT_SAVE_OCCUPIED, DEFAULT_SAVE_FREE = 65, 0


class MapError(Exception):
    """Base class: every message names the file and the problem."""


class MapFileNotFoundError(MapError, FileNotFoundError):
    pass


class MapYamlError(MapError, ValueError):
    pass


class MapImageError(MapError, ValueError):
    pass


@dataclass(frozen=True)
class MapConfig:
    image: Path
    resolution: float
    origin: tuple
    negate: bool = False
    occupied_thresh: float = 0.65
    free_thresh: float = 0.196
    mode: str = "trinary"
    yaml_path: Path = None
    warnings: tuple = ()


@dataclass
class OccupancyMap:
    """Cells as int8 (-1 unknown, 0 free .. 100 occupied); data[0] is the bottom row."""

    data: np.ndarray
    resolution: float
    origin: tuple = (0.0, 0.0, 0.0)
    config: MapConfig = field(default=None, repr=False)

    @property
    def height(self):
        return int(self.data.shape[0])

    @property
    def width(self):
        return int(self.data.shape[1])

    def flat(self):
        """Row-major cells, bottom row first: OccupancyGrid.data order."""
        return np.ascontiguousarray(self.data).reshape(-1)

    @classmethod
    def from_flat(cls, cells, width, height, resolution, origin):
        cells = np.asarray(cells)
        if width <= 0 or height <= 0:
            raise MapError(f"the map is empty ({width} x {height} cells)")
        if cells.size != width * height:
            raise MapError(
                f"the map holds {cells.size} cells but says it is {width} x {height} "
                f"({width * height} cells)"
            )
        data = cells.astype(np.int16).astype(np.int8).reshape(height, width)
        return cls(data, float(resolution), tuple(float(v) for v in origin))


# -- reading -------------------------------------------------------------------------


def _number(raw, key, where):
    if isinstance(raw, bool) or not isinstance(raw, (int, float)):
        raise MapYamlError(f"{where}: '{key}' must be a number, got {raw!r}")
    value = float(raw)
    if not math.isfinite(value):
        raise MapYamlError(f"{where}: '{key}' must be finite, got {raw!r}")
    return value


def _negate_flag(raw, where):
    if isinstance(raw, bool):
        return raw
    if isinstance(raw, int) and raw in (0, 1):
        return bool(raw)
    raise MapYamlError(f"{where}: 'negate' must be 0 or 1, got {raw!r}")


def check_thresholds(occupied, free, where):
    for key, value in (("occupied_thresh", occupied), ("free_thresh", free)):
        if not 0.0 <= value <= 1.0:
            raise MapYamlError(f"{where}: '{key}' must be between 0 and 1, got {value}")
    if free >= occupied:
        raise MapYamlError(
            f"{where}: free_thresh ({free}) must be smaller than occupied_thresh ({occupied})"
        )


def check_mode(mode, where):
    if mode not in MODES:
        raise MapYamlError(f"{where}: unknown mode {mode!r} (expected trinary, scale or raw)")
    return mode


def parse_map_yaml(text, yaml_path):
    """Validate a map YAML's text; `yaml_path` locates the image and names errors."""
    yaml_path = Path(yaml_path)
    where = str(yaml_path)
    try:
        doc = yaml.safe_load(text)
    except yaml.YAMLError as err:
        raise MapYamlError(f"{where}: not valid YAML: {err}") from None
    if not isinstance(doc, dict):
        raise MapYamlError(f"{where}: expected a mapping of keys (image, resolution, ...)")
    missing = [key for key in REQUIRED_KEYS if key not in doc]
    if missing:
        raise MapYamlError(f"{where}: missing key(s): {', '.join(missing)}")
    warnings = tuple(
        f"{where}: unknown key '{key}' ignored" for key in doc if key not in KNOWN_KEYS
    )
    image = doc["image"]
    if not isinstance(image, str) or not image.strip():
        raise MapYamlError(f"{where}: 'image' must be a file name, got {image!r}")
    resolution = _number(doc["resolution"], "resolution", where)
    if resolution <= 0:
        raise MapYamlError(f"{where}: 'resolution' must be positive, got {resolution}")
    origin = doc["origin"]
    if not isinstance(origin, (list, tuple)) or len(origin) != 3:
        raise MapYamlError(f"{where}: 'origin' must be a list [x, y, yaw], got {origin!r}")
    origin = tuple(_number(v, "origin", where) for v in origin)
    occupied = _number(doc["occupied_thresh"], "occupied_thresh", where)
    free = _number(doc["free_thresh"], "free_thresh", where)
    check_thresholds(occupied, free, where)
    mode = check_mode(doc.get("mode", "trinary"), where)
    image_path = Path(image)
    if not image_path.is_absolute():
        image_path = yaml_path.parent / image_path
    return MapConfig(
        image=image_path,
        resolution=resolution,
        origin=origin,
        negate=_negate_flag(doc["negate"], where),
        occupied_thresh=occupied,
        free_thresh=free,
        mode=mode,
        yaml_path=yaml_path,
        warnings=warnings,
    )


def _cwd_note(path):
    return "" if Path(path).is_absolute() else f" (looked in {Path.cwd()})"


def read_map_yaml(yaml_path):
    yaml_path = Path(yaml_path)
    try:
        text = yaml_path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise MapFileNotFoundError(
            f"{yaml_path}: map YAML file not found{_cwd_note(yaml_path)}"
        ) from None
    except IsADirectoryError:
        raise MapYamlError(f"{yaml_path}: is a directory, not a map YAML file") from None
    except UnicodeDecodeError:
        raise MapYamlError(f"{yaml_path}: not a text file (is it the image?)") from None
    except OSError as err:
        raise MapYamlError(f"{yaml_path}: cannot read: {err.strerror or err}") from None
    return parse_map_yaml(text, yaml_path)


def read_grey_image(path):
    """Load an image as grey values 0..255 (float, row 0 at the top).

    Returns (grey, opaque): opaque is a bool array (False where alpha is 0) or None
    when the image has no alpha channel. Colour channels are averaged; 16-bit images
    are scaled to 0..255.
    """
    path = Path(path)
    try:
        with open(path, "rb") as handle:
            data = handle.read()
    except FileNotFoundError:
        raise MapFileNotFoundError(f"{path}: map image not found{_cwd_note(path)}") from None
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
    import io

    from PIL import Image, UnidentifiedImageError

    try:
        image = Image.open(io.BytesIO(data))
        image.load()
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


def load_map_from_config(config):
    grey, opaque = read_grey_image(config.image)
    if grey.size == 0:
        raise MapImageError(f"{config.image}: image has no pixels")
    cells = grey_to_occupancy(
        grey, opaque, config.negate, config.occupied_thresh, config.free_thresh, config.mode
    )
    return OccupancyMap(cells[::-1].copy(), config.resolution, config.origin, config)


def load_map(yaml_path):
    """Load a map YAML and its image; raises MapError subclasses naming the file."""
    return load_map_from_config(read_map_yaml(yaml_path))


def load_image_map(image_path, resolution, origin=(0.0, 0.0, 0.0), negate=False):
    """The deprecated `map_server IMAGE RESOLUTION` form: default thresholds, trinary."""
    where = str(image_path)
    resolution = _number(resolution, "resolution", where)
    if resolution <= 0:
        raise MapYamlError(f"{where}: resolution must be positive, got {resolution}")
    origin = tuple(_number(v, "origin", where) for v in origin)
    config = MapConfig(
        image=Path(image_path), resolution=resolution, origin=origin, negate=bool(negate)
    )
    return load_map_from_config(config)


# -- saving --------------------------------------------------------------------------


def occupancy_to_pgm(data, occupied=DEFAULT_SAVE_OCCUPIED, free=DEFAULT_SAVE_FREE):
    """map_saver's rule: 0..free -> 254, >= occupied -> 0, else 205; returns top row first."""
    values = np.asarray(data).astype(np.int16)
    pixels = np.full(values.shape, PGM_UNKNOWN, dtype=np.uint8)
    pixels[(values >= 0) & (values <= free)] = PGM_FREE
    pixels[values >= occupied] = PGM_OCCUPIED
    return pixels[::-1].copy()


def check_save_thresholds(occupied, free):
    if not 1 <= occupied <= 100:
        raise ValueError(f"occupied threshold must be between 1 and 100, got {occupied}")
    if not 0 <= free <= 100:
        raise ValueError(f"free threshold must be between 0 and 100, got {free}")
    if free >= occupied:
        raise ValueError(f"free threshold ({free}) must be smaller than occupied ({occupied})")


def _plain(value):
    return float(value) + 0.0  # no "-0.000000" in the YAML


def map_yaml_text(image_name, resolution, origin):
    """The YAML map_saver writes (the book shows this exact layout)."""
    name = image_name
    try:
        if yaml.safe_load(f"image: {name}") != {"image": name}:
            name = json.dumps(name)
    except yaml.YAMLError:
        name = json.dumps(name)
    x, y, yaw = (_plain(v) for v in origin)
    return (
        f"image: {name}\n"
        f"resolution: {_plain(resolution):f}\n"
        f"origin: [{x:f}, {y:f}, {yaw:f}]\n"
        "negate: 0\n"
        f"occupied_thresh: {SAVED_OCCUPIED_THRESH}\n"
        f"free_thresh: {SAVED_FREE_THRESH}\n\n"
    )


def map_base_name(name):
    """`-f NAME` may be given as NAME.pgm or NAME.yaml; both mean NAME."""
    name = str(name)
    for suffix in (".pgm", ".yaml"):
        if name.endswith(suffix) and len(name) > len(suffix):
            return name[: -len(suffix)]
    return name


def save_map(base, omap, occupied=DEFAULT_SAVE_OCCUPIED, free=DEFAULT_SAVE_FREE):
    """Write BASE.pgm and BASE.yaml atomically; returns (pgm_path, yaml_path).

    On any failure the previous files (if any) stay as they were.
    """
    check_save_thresholds(occupied, free)
    data = np.asarray(omap.data)
    if data.ndim != 2 or data.size == 0:
        raise MapError(f"cannot save an empty map ({data.shape})")
    if not (math.isfinite(omap.resolution) and omap.resolution > 0):
        raise MapError(f"cannot save a map with resolution {omap.resolution}")
    if len(omap.origin) != 3 or not all(math.isfinite(v) for v in omap.origin):
        raise MapError(f"cannot save a map with origin {omap.origin}")
    base = Path(map_base_name(base))
    pgm_path = base.parent / (base.name + ".pgm")
    yaml_path = base.parent / (base.name + ".yaml")
    comment = f"CREATOR: map_saver {omap.resolution:.3f} m/pix"
    image = pgm.encode_pgm(occupancy_to_pgm(data, occupied, free), comment)
    text = map_yaml_text(pgm_path.name, omap.resolution, omap.origin)
    write_files_atomically({pgm_path: image, yaml_path: text.encode("utf-8")})
    return pgm_path, yaml_path


# -- geometry --------------------------------------------------------------------------


def yaw_to_quaternion(yaw):
    """(x, y, z, w) of a rotation by `yaw` about z."""
    return (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))


def quaternion_to_yaw(x, y, z, w):
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
