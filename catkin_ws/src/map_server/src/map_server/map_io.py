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

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from map_server import pgm
from map_server.atomic import write_files_atomically
from map_server.errors import MapError, MapFileNotFoundError, MapImageError, MapYamlError
from map_server.map_image import (
    DEFAULT_SAVE_FREE,
    DEFAULT_SAVE_OCCUPIED,
    PGM_FREE,
    PGM_OCCUPIED,
    PGM_UNKNOWN,
    grey_to_occupancy,
    occupancy_to_pgm,
    read_grey_image,
)
from map_server.map_yaml import (
    KNOWN_KEYS,
    MODES,
    REQUIRED_KEYS,
    MapConfig,
    check_mode,
    check_resolution,
    check_thresholds,
    map_yaml_text,
    number,
    parse_map_yaml,
    read_map_yaml,
)

__all__ = [
    "DEFAULT_SAVE_FREE",
    "DEFAULT_SAVE_OCCUPIED",
    "KNOWN_KEYS",
    "MODES",
    "PGM_FREE",
    "PGM_OCCUPIED",
    "PGM_UNKNOWN",
    "REQUIRED_KEYS",
    "MapConfig",
    "MapError",
    "MapFileNotFoundError",
    "MapImageError",
    "MapYamlError",
    "OccupancyMap",
    "check_mode",
    "check_save_thresholds",
    "check_thresholds",
    "grey_to_occupancy",
    "load_image_map",
    "load_map",
    "load_map_from_config",
    "map_base_name",
    "map_yaml_text",
    "occupancy_to_pgm",
    "parse_map_yaml",
    "read_grey_image",
    "read_map_yaml",
    "save_map",
]


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
    resolution = number(resolution, "resolution", where)
    if resolution <= 0:
        raise MapYamlError(f"{where}: resolution must be positive, got {resolution}")
    check_resolution(resolution, where)
    origin = tuple(number(v, "origin", where) for v in origin)
    config = MapConfig(
        image=Path(image_path), resolution=resolution, origin=origin, negate=bool(negate)
    )
    return load_map_from_config(config)


# -- saving ----------------------------------------------------------------------------


def check_save_thresholds(occupied, free):
    if not 1 <= occupied <= 100:
        raise ValueError(f"occupied threshold must be between 1 and 100, got {occupied}")
    if not 0 <= free <= 100:
        raise ValueError(f"free threshold must be between 0 and 100, got {free}")
    if free >= occupied:
        raise ValueError(f"free threshold ({free}) must be smaller than occupied ({occupied})")


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
