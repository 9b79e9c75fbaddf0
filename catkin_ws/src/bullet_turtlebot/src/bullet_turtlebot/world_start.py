"""Where the simulator puts the robot in a world: the world file's `start` pose.

The same resolution of a world's name as the simulator's (world_spec.cpp,
resolve_world_path): a name with a '/' or ending in .yaml is a path, anything else a shipped
world in `worlds_dir`. A world file without `start` starts the robot at the origin.
"""

import math
from pathlib import Path

import yaml


def world_path(world, worlds_dir):
    if "/" in world or (len(world) > 5 and world.endswith(".yaml")):
        return Path(world)
    return Path(worlds_dir) / f"{world}.yaml"


def start_pose(world, worlds_dir):
    """(x, y, yaw) of the world's start. Raises ValueError naming the file and the fix."""
    path = world_path(world, worlds_dir)
    try:
        spec = yaml.safe_load(path.read_text())
    except OSError as err:
        raise ValueError(f"cannot read world file {path}: {err.strerror}") from err
    except yaml.YAMLError as err:
        raise ValueError(f"{path}: not YAML ({err})") from err
    start = (spec or {}).get("start", [0.0, 0.0, 0.0]) if isinstance(spec, dict) else None
    if (
        not isinstance(start, list)
        or len(start) != 3
        or not all(isinstance(v, (int, float)) and math.isfinite(v) for v in start)
    ):
        raise ValueError(f"{path}: 'start' must be [x, y, yaw] in metres and radians")
    return tuple(float(v) for v in start)
