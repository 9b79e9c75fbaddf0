"""Where the simulator puts the robot in a world: the world file's `start` pose.

The same resolution of a world's name as the simulator's (world_spec.cpp,
resolve_world_path): a name with a '/' or ending in .yaml is a path, anything else a shipped
world in `worlds_dir`. A world file without `start` starts the robot at the origin.
"""

import math
from pathlib import Path

import yaml
from rosbook_env.files import special_file_note
from rosbook_env.yaml_files import YamlCppLoader, load_unique


def world_path(world, worlds_dir):
    if "/" in world or (len(world) > 5 and world.endswith(".yaml")):
        return Path(world)
    return Path(worlds_dir) / f"{world}.yaml"


def start_pose(world, worlds_dir):
    """(x, y, yaw) of the world's start. Raises ValueError naming the file and the fix.

    As the simulator (world_spec.cpp): `start` is [x, y] or [x, y, yaw], metres within 1e6
    of the origin, a yaw within 1000 rad."""
    path = world_path(world, worlds_dir)
    try:
        special = special_file_note(path)
        if special:
            raise ValueError(f"world file {path}: {special}; give a world YAML file")
        # yaml-cpp's numbers (as the simulator reads the file), no duplicate keys
        spec = load_unique(path.read_text(), YamlCppLoader)
    except OSError as err:
        raise ValueError(f"cannot read world file {path}: {err.strerror}") from err
    except yaml.YAMLError as err:
        raise ValueError(f"{path}: not YAML ({err})") from err
    except RecursionError:  # PyYAML recurses once per nesting level
        raise ValueError(f"{path}: nested too deeply to be a world file") from None
    except UnicodeDecodeError:
        raise ValueError(f"{path}: not a text file; give a world YAML file") from None
    start = (spec or {}).get("start", [0.0, 0.0, 0.0]) if isinstance(spec, dict) else None
    if (
        not isinstance(start, list)
        or len(start) not in (2, 3)
        or not all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
            for v in start
        )
        or not all(abs(v) <= limit for v, limit in zip(start, (1e6, 1e6, 1e3), strict=False))
    ):
        raise ValueError(
            f"{path}: 'start' must be [x, y] or [x, y, yaw]: metres within 1e6 of the origin "
            "and radians"
        )
    return tuple(float(v) for v in start) + ((0.0,) if len(start) == 2 else ())
