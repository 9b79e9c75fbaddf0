"""Occupancy grids placed in the world, (cells, resolution, origin), and the wall metric.

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


def distance_to_walls(points, truth, reach):
    """Distance (metres) from each world point (N x 2) to the centre of the nearest occupied
    cell of the `truth` grid, looking `reach` metres around it; inf when none is that near
    (or the point is off the grid)."""
    cells, resolution, (ox, oy, oth) = truth
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    c, s = math.cos(-oth), math.sin(-oth)
    dx, dy = points[:, 0] - ox, points[:, 1] - oy
    u, v = (c * dx - s * dy) / resolution, (s * dx + c * dy) / resolution  # in cells
    col, row = np.floor(u).astype(int), np.floor(v).astype(int)
    walls = cells >= OCCUPIED
    best = np.full(len(points), np.inf)
    span = int(math.ceil(reach / resolution)) + 1
    for dr in range(-span, span + 1):
        for dc in range(-span, span + 1):
            r, k = row + dr, col + dc
            inside = (r >= 0) & (r < cells.shape[0]) & (k >= 0) & (k < cells.shape[1])
            wall = np.zeros(len(points), dtype=bool)
            wall[inside] = walls[r[inside], k[inside]]
            d = np.hypot(u - (k + 0.5), v - (r + 0.5)) * resolution
            best = np.where(wall & (d < best), d, best)
    return best


def near_wall_share(points, truth, tolerance):
    """THE wall metric: the share of `points` (world x, y: the centres of the SLAM map's
    occupied cells, placed in the world) that lie within `tolerance` + half a truth cell of
    the centre of an occupied cell of the `truth` grid; NaN when there are no points.

    Why the half cell: a true wall cell says "a wall surface passes somewhere in this
    square", so its centre may lie up to half a cell from the surface it stands for. With it,
    a perfect map on the truth's own grid scores 100 %, and so does one shifted by up to
    `tolerance`; a cell any further from every true wall misses. Points off the truth grid
    miss. The distance is measured from the point itself (not from the truth cell it falls
    in), so a SLAM map turned against the truth grid is judged as finely as an aligned one.
    """
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    if not len(points):
        return float("nan")
    reach = tolerance + 0.5 * truth[1]
    return float((distance_to_walls(points, truth, reach) <= reach + 1e-9).mean())
