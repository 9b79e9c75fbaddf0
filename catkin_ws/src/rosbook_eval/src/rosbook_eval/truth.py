"""The world's true occupancy grid, from the simulator's own rasterizer.

bullet_turtlebot's `world_to_map` draws a world (its map image, boxes and cylinders) the way
the simulator builds it, so every score is measured against the one truth the robot drove in.
"""

import subprocess
import tempfile
from pathlib import Path

from map_server.map_io import load_map

# The SLAM maps' resolution (slam_gmapping's delta, map_saver keeps it).
TRUTH_RESOLUTION = 0.05


def write_truth_map(world, base, resolution=TRUTH_RESOLUTION):
    """Run `world_to_map` on `world` (a shipped world's name, a world YAML or a map_server
    YAML); it writes BASE.pgm and BASE.yaml. Raises RuntimeError with its message on failure."""
    cmd = ["rosrun", "bullet_turtlebot", "world_to_map", str(world), "-f", str(base)]
    done = subprocess.run([*cmd, "--resolution", f"{resolution:g}"], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(done.stderr.strip() or f"world_to_map exited {done.returncode}")
    return Path(f"{base}.yaml")


def load_grid(yaml_path):
    """A map_server map as a grid (cells, resolution, origin), read by map_server's loader."""
    loaded = load_map(str(yaml_path))
    return loaded.data, loaded.resolution, loaded.origin


def truth_grid(world, resolution=TRUTH_RESOLUTION):
    """The world's true grid (cells, resolution, origin), via a temporary folder."""
    with tempfile.TemporaryDirectory() as folder:
        return load_grid(write_truth_map(world, Path(folder) / "truth", resolution))
