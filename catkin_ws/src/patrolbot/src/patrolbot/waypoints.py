"""Patrol waypoints: the book's [(x, y, z), (qx, qy, qz, qw)] pairs, read from YAML."""

import math

import yaml
from rosbook_env.yaml_files import load_unique


class WaypointError(ValueError):
    pass


def pose_from_xy_yaw(x, y, yaw):
    return [(x, y, 0.0), (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))]


def load_waypoints(path):
    """A YAML list of waypoints, each {x, y, yaw} (yaw in radians, default 0), in the
    `map` frame. Raises WaypointError naming the file and the entry."""
    try:
        with open(path) as f:
            data = load_unique(f)  # a key given twice (x: 1 ... x: 2) is an error
    except (OSError, yaml.YAMLError) as e:
        raise WaypointError(f"{path}: {e}") from None
    if isinstance(data, dict):
        data = data.get("waypoints")
    if not isinstance(data, list) or not data:
        raise WaypointError(f"{path}: expected a non-empty list of {{x, y, yaw}} waypoints")
    poses = []
    for i, entry in enumerate(data):
        try:
            x, y = float(entry["x"]), float(entry["y"])
            yaw = float(entry.get("yaw", 0.0))
        except (TypeError, KeyError, ValueError):
            raise WaypointError(f"{path}: waypoint {i} must have numbers x, y (and yaw)") from None
        if not all(math.isfinite(v) for v in (x, y, yaw)):
            raise WaypointError(f"{path}: waypoint {i} has a non-finite value")
        poses.append(pose_from_xy_yaw(x, y, yaw))
    return poses
