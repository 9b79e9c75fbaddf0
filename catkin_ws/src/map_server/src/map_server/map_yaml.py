"""The map YAML file: parse and validate it (map_server), and write it (map_saver)."""

import json
import math
from dataclasses import dataclass
from pathlib import Path

import yaml
from rosbook_env.files import looked_in_note, resolve_user_path, special_file_note
from rosbook_env.yaml_files import YamlCppLoader, load_unique

from map_server.errors import MapFileNotFoundError, MapYamlError

MODES = ("trinary", "scale", "raw")
REQUIRED_KEYS = ("image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh")
KNOWN_KEYS = frozenset(REQUIRED_KEYS + ("mode",))

# The thresholds map_saver's YAML declares (its pixels 254/0/205 read back as 0/100/-1).
SAVED_OCCUPIED_THRESH, SAVED_FREE_THRESH = 0.65, 0.196

# nav_msgs/MapMetaData carries the resolution as a float32: its smallest normal and its
# largest value.
FLOAT32_TINY, FLOAT32_MAX = 1.1754943508222875e-38, 3.4028234663852886e38


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


def number(raw, key, where):
    """A finite float from a YAML value; booleans and strings are refused."""
    if isinstance(raw, bool) or not isinstance(raw, (int, float)):
        raise MapYamlError(f"{where}: '{key}' must be a number, got {raw!r}")
    try:
        value = float(raw)
    except OverflowError:  # an integer with hundreds of digits
        value = math.inf
    if not math.isfinite(value):
        raise MapYamlError(f"{where}: '{key}' must be finite, got {raw!r}")
    return value


def check_resolution(resolution, where):
    """A positive resolution that nav_msgs/MapMetaData's float32 field can carry."""
    if resolution <= 0:
        raise MapYamlError(f"{where}: 'resolution' must be positive, got {resolution}")
    if not FLOAT32_TINY <= resolution <= FLOAT32_MAX:
        raise MapYamlError(
            f"{where}: 'resolution' {resolution} does not fit MapMetaData's float32 "
            "(metres per cell, e.g. 0.05)"
        )
    return resolution


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
        doc = load_unique(text, YamlCppLoader)  # yaml-cpp's numbers, no duplicate keys
    except yaml.YAMLError as err:
        raise MapYamlError(f"{where}: not valid YAML: {err}") from None
    except RecursionError:  # PyYAML's parser recurses once per nesting level
        raise MapYamlError(f"{where}: nested too deeply to be a map YAML") from None
    if not isinstance(doc, dict):
        raise MapYamlError(f"{where}: expected a mapping of keys (image, resolution, ...)")
    missing = [key for key in REQUIRED_KEYS if key not in doc]
    if missing:
        raise MapYamlError(f"{where}: missing key(s): {', '.join(missing)}")
    warnings = tuple(
        f"{where}: unknown key '{key}' ignored" for key in doc if key not in KNOWN_KEYS
    )
    image = doc["image"]
    if not isinstance(image, str) or not image.strip() or "\0" in image:
        raise MapYamlError(f"{where}: 'image' must be a file name, got {image!r}")
    resolution = check_resolution(number(doc["resolution"], "resolution", where), where)
    origin = doc["origin"]
    if not isinstance(origin, (list, tuple)) or len(origin) != 3:
        raise MapYamlError(f"{where}: 'origin' must be a list [x, y, yaw], got {origin!r}")
    origin = tuple(number(v, "origin", where) for v in origin)
    occupied = number(doc["occupied_thresh"], "occupied_thresh", where)
    free = number(doc["free_thresh"], "free_thresh", where)
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


def read_map_yaml(yaml_path):
    """Read and check a map YAML. A relative path missing from the cwd is looked for in the
    launching shell's folder (roslaunch runs nodes in ~/.ros): rosbook_env.files."""
    given = yaml_path
    yaml_path = Path(resolve_user_path(yaml_path))
    special = special_file_note(yaml_path)
    if special:
        raise MapYamlError(f"{yaml_path}: {special}; give the map YAML file")
    try:
        text = yaml_path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise MapFileNotFoundError(
            f"{yaml_path}: map YAML file not found{looked_in_note(given)}"
        ) from None
    except IsADirectoryError:
        raise MapYamlError(f"{yaml_path}: is a directory, not a map YAML file") from None
    except UnicodeDecodeError:
        raise MapYamlError(f"{yaml_path}: not a text file (is it the image?)") from None
    except OSError as err:
        raise MapYamlError(f"{yaml_path}: cannot read: {err.strerror or err}") from None
    return parse_map_yaml(text, yaml_path)


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
