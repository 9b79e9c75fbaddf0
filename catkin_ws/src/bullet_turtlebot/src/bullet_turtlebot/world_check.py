"""Check a world file the way a robot would meet it: walls, boxes and cylinders rasterised
on the PGM's grid, free space eroded by the robot's radius, flood-filled from the start.

    grid = load_grid("worlds/ring.yaml")
    print(problems(grid))                     # [] when the world is fit to explore

Needs numpy and scipy (not the generator, which is plain Python).
"""

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from rosbook_env.yaml_files import YamlCppLoader, load_unique
from scipy import ndimage

ROBOT_RADIUS = 0.18  # m: the Kobuki
SWEEP_MARGIN = 0.02  # m: the simulator's clearance around the robot
START_CLEARANCE = 0.5  # m: free space wanted around the start pose


@dataclass
class Grid:
    """Occupancy on the world file's own grid: occupied[i, j] is the cell whose centre is
    (origin x + (j + 0.5) res, origin y + (i + 0.5) res); row 0 is the bottom."""

    occupied: np.ndarray
    resolution: float
    origin: tuple
    start: tuple

    def cell(self, x, y):
        return (
            int(math.floor((y - self.origin[1]) / self.resolution)),
            int(math.floor((x - self.origin[0]) / self.resolution)),
        )

    def centres(self):
        rows, cols = self.occupied.shape
        xs = self.origin[0] + (np.arange(cols) + 0.5) * self.resolution
        ys = self.origin[1] + (np.arange(rows) + 0.5) * self.resolution
        return np.meshgrid(xs, ys)


def read_pgm(path):
    data = Path(path).read_bytes()
    fields = data.split(maxsplit=4)
    if fields[0] != b"P5" or fields[3] != b"255":
        raise ValueError(f"{path}: only 8-bit binary PGMs are read here")
    width, height = int(fields[1]), int(fields[2])
    return np.frombuffer(data[-width * height :], dtype=np.uint8).reshape(height, width)


def load_grid(yaml_path):
    """The world's walls and primitives as a Grid (cells whose centre is inside a solid)."""
    yaml_path = Path(yaml_path)
    spec = load_unique(yaml_path.read_text(), YamlCppLoader)  # as the simulator reads it
    pixels = read_pgm(yaml_path.parent / spec["image"])
    occupancy = (255 - pixels.astype(float)) / 255
    if spec.get("negate", 0):
        occupancy = pixels.astype(float) / 255
    occupied = np.flipud(occupancy > spec.get("occupied_thresh", 0.65)).copy()
    grid = Grid(occupied, spec["resolution"], tuple(spec["origin"][:2]), tuple(spec["start"]))
    xs, ys = grid.centres()
    for box in spec.get("boxes") or []:
        (bx, by, yaw), (sx, sy, _) = box["pose"], box["size"]
        along = (xs - bx) * math.cos(yaw) + (ys - by) * math.sin(yaw)
        across = -(xs - bx) * math.sin(yaw) + (ys - by) * math.cos(yaw)
        grid.occupied |= (np.abs(along) <= sx / 2) & (np.abs(across) <= sy / 2)
    for cylinder in spec.get("cylinders") or []:
        cx, cy = cylinder["position"]
        grid.occupied |= (xs - cx) ** 2 + (ys - cy) ** 2 <= cylinder["radius"] ** 2
    return grid


def clearance(grid):
    """Metres from each cell centre to the nearest solid (0 inside solids)."""
    distance = ndimage.distance_transform_edt(~grid.occupied) * grid.resolution
    return np.maximum(distance - grid.resolution / 2, 0.0)


def passable(grid, radius=ROBOT_RADIUS + SWEEP_MARGIN):
    """Cells where the robot's centre can be."""
    return clearance(grid) >= radius


def reachable(grid, radius=ROBOT_RADIUS + SWEEP_MARGIN):
    """Passable cells 4-connected to the start cell."""
    labels, _ = ndimage.label(passable(grid, radius))
    start = labels[grid.cell(*grid.start[:2])]
    return labels == start if start else np.zeros_like(grid.occupied)


def holes(region):
    """The pieces of the region's complement that do not reach the grid's border (obstacles
    a robot can drive all the way round), largest first: (cells, (row slice, col slice))."""
    labels, count = ndimage.label(~region, structure=np.ones((3, 3)))
    border = set(np.unique(np.concatenate([labels[0], labels[-1], labels[:, 0], labels[:, -1]])))
    sizes = ndimage.sum_labels(np.ones_like(labels), labels, index=np.arange(1, count + 1))
    boxes = ndimage.find_objects(labels)
    found = [
        (int(size), boxes[label - 1])
        for label, size in enumerate(sizes, start=1)
        if label not in border
    ]
    return sorted(found, key=lambda hole: -hole[0])


def problems(grid):
    """What makes the world unfit to explore: a cramped start, or free space the robot can
    never reach. Empty when all is well."""
    found = []
    start_clearance = clearance(grid)[grid.cell(*grid.start[:2])]
    if start_clearance < START_CLEARANCE - grid.resolution:
        found.append(f"start {grid.start[:2]} only {start_clearance:.2f} m from an obstacle")
    lost = passable(grid) & ~reachable(grid)
    if lost.any():
        i, j = np.argwhere(lost)[0]
        x = grid.origin[0] + (j + 0.5) * grid.resolution
        y = grid.origin[1] + (i + 0.5) * grid.resolution
        area = lost.sum() * grid.resolution**2
        found.append(f"{area:.2f} m2 of free space unreachable from the start ({x:.2f}, {y:.2f})")
    return found
