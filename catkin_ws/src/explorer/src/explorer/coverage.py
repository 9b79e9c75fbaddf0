"""How much of a world an exploration mapped: the share of the ground truth's free cells
reachable from the start (connected to it through free cells) that the map knows, free
or occupied. Grids are in OccupancyGrid order (row 0 at the origin's y)."""

import math

import numpy as np
from scipy import ndimage


def reachable_free(occupied, start_cell):
    """Free cells 4-connected to `start_cell` (row, col) through free cells; all False if
    the start is outside the grid or occupied."""
    row, col = start_cell
    height, width = occupied.shape
    if not (0 <= row < height and 0 <= col < width) or occupied[row, col]:
        return np.zeros(occupied.shape, dtype=bool)
    labels, _ = ndimage.label(~occupied)
    return labels == labels[row, col]


def known_at(values, resolution, origin, xs, ys):
    """Whether the map (values: -1 unknown; origin: world x, y, yaw of cell (0, 0)'s
    corner) knows the cells under the world points (xs, ys); False outside it."""
    ox, oy, oth = origin
    c, s = math.cos(oth), math.sin(oth)
    dx, dy = np.asarray(xs) - ox, np.asarray(ys) - oy
    col = np.floor((c * dx + s * dy) / resolution).astype(int)
    row = np.floor((-s * dx + c * dy) / resolution).astype(int)
    inside = (row >= 0) & (row < values.shape[0]) & (col >= 0) & (col < values.shape[1])
    known = np.zeros(np.shape(xs), dtype=bool)
    known[inside] = values[row[inside], col[inside]] != -1
    return known


def coverage(truth_occupied, truth_resolution, truth_origin, start, values, resolution, origin):
    """Share (0..1) of the truth's free cells reachable from `start` (world x, y) that the
    map (values, resolution, origin as in known_at, placed in the world) knows."""
    tx, ty = truth_origin[:2]
    start_cell = (
        int(math.floor((start[1] - ty) / truth_resolution)),
        int(math.floor((start[0] - tx) / truth_resolution)),
    )
    region = reachable_free(truth_occupied, start_cell)
    if not region.any():
        return float("nan")
    rows, cols = np.nonzero(region)
    xs = tx + (cols + 0.5) * truth_resolution
    ys = ty + (rows + 0.5) * truth_resolution
    return float(known_at(values, resolution, origin, xs, ys).mean())
