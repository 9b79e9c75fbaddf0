"""Occupancy grids placed in the world: (cells, resolution, origin).

cells is a 2-D array in OccupancyGrid order (row 0 at the bottom; -1 unknown, 0 free,
100 occupied) and origin the world pose (x, y, yaw) of cell (0, 0)'s outer corner.
"""

import math

import numpy as np

OCCUPIED = 65


def to_world(grid, cols, rows):
    """World coordinates of (fractional) cell coordinates."""
    _, resolution, (ox, oy, oth) = grid
    x, y = cols * resolution, rows * resolution
    c, s = math.cos(oth), math.sin(oth)
    return np.column_stack((ox + c * x - s * y, oy + s * x + c * y))


def cell_centres(grid, mask):
    """World coordinates of the centres of the cells where `mask` is true."""
    rows, cols = np.nonzero(mask)
    return to_world(grid, cols + 0.5, rows + 0.5)


def occupied_points(grid):
    return cell_centres(grid, grid[0] >= OCCUPIED)


def corners(grid):
    rows, cols = grid[0].shape
    return to_world(grid, np.array([0, cols, 0, cols]), np.array([0, 0, rows, rows]))


def sample(grid, xs, ys):
    """Cell values at world points (arrays of any shape); -2 outside the grid."""
    cells, resolution, (ox, oy, oth) = grid
    c, s = math.cos(-oth), math.sin(-oth)
    dx, dy = np.asarray(xs) - ox, np.asarray(ys) - oy
    col = np.floor((c * dx - s * dy) / resolution).astype(int)
    row = np.floor((s * dx + c * dy) / resolution).astype(int)
    inside = (row >= 0) & (row < cells.shape[0]) & (col >= 0) & (col < cells.shape[1])
    values = np.full(np.shape(xs), -2, dtype=np.int16)
    values[inside] = cells[row[inside], col[inside]]
    return values


def dilate(mask, radius_cells, resolution, tolerance):
    """Cells within `tolerance` metres (centre to centre) of a true cell of `mask`."""
    near = np.zeros_like(mask)
    rows, cols = mask.shape
    for dr in range(-radius_cells, radius_cells + 1):
        for dc in range(-radius_cells, radius_cells + 1):
            if math.hypot(dr, dc) * resolution > tolerance + 0.5 * resolution:
                continue
            near[max(dr, 0) : rows + min(dr, 0), max(dc, 0) : cols + min(dc, 0)] |= mask[
                max(-dr, 0) : rows + min(-dr, 0), max(-dc, 0) : cols + min(-dc, 0)
            ]
    return near
