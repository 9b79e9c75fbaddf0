"""Occupancy grids as numpy arrays: cell classes, geometry, cropping and downsampling.

Cells are indexed [row, col] with row = y and col = x, as in nav_msgs/OccupancyGrid's
row-major data (row 0 at the map origin's y).
"""

from dataclasses import dataclass

import numpy as np

FREE = 0
UNKNOWN = 1
OCCUPIED = 2


@dataclass(frozen=True)
class GridGeometry:
    """Where a grid lies in its frame: cell size, origin of cell (0, 0)'s corner, shape."""

    resolution: float
    origin_x: float
    origin_y: float
    width: int
    height: int

    def to_cell(self, x, y):
        """(row, col) of the cell holding the point (x, y); may lie outside the grid."""
        col = np.floor((np.asarray(x) - self.origin_x) / self.resolution).astype(int)
        row = np.floor((np.asarray(y) - self.origin_y) / self.resolution).astype(int)
        return row, col

    def to_world(self, row, col):
        """Centre (x, y) of cell (row, col)."""
        x = self.origin_x + (np.asarray(col) + 0.5) * self.resolution
        y = self.origin_y + (np.asarray(row) + 0.5) * self.resolution
        return x, y

    def contains(self, row, col):
        return (row >= 0) & (row < self.height) & (col >= 0) & (col < self.width)

    def sub(self, row0, col0, height, width, factor=1):
        """The geometry of a window starting at (row0, col0), downsampled by `factor`."""
        return GridGeometry(
            self.resolution * factor,
            self.origin_x + col0 * self.resolution,
            self.origin_y + row0 * self.resolution,
            width,
            height,
        )


def classify(values, free_threshold=25, occupied_threshold=65):
    """OccupancyGrid values (-1 unknown, 0..100) to FREE/UNKNOWN/OCCUPIED classes (uint8).

    Values between the thresholds count as unknown; so do values outside -1..100.
    """
    values = np.asarray(values)
    classes = np.full(values.shape, UNKNOWN, dtype=np.uint8)
    classes[(values >= 0) & (values <= free_threshold)] = FREE
    classes[(values >= occupied_threshold) & (values <= 100)] = OCCUPIED
    return classes


def known_window(classes, margin):
    """(row0, col0, row1, col1) bounding the known cells plus `margin` cells, or None."""
    rows = np.flatnonzero((classes != UNKNOWN).any(axis=1))
    if rows.size == 0:
        return None
    cols = np.flatnonzero((classes != UNKNOWN).any(axis=0))
    height, width = classes.shape
    return (
        max(0, rows[0] - margin),
        max(0, cols[0] - margin),
        min(height, rows[-1] + 1 + margin),
        min(width, cols[-1] + 1 + margin),
    )


def downsample(classes, factor):
    """Coarser grid: a block is OCCUPIED if any cell is, else FREE if at least half its
    cells are free, else UNKNOWN. Edge blocks are padded with UNKNOWN."""
    if factor <= 1:
        return classes.copy()
    height, width = classes.shape
    ph, pw = -height % factor, -width % factor
    padded = np.pad(classes, ((0, ph), (0, pw)), constant_values=UNKNOWN)
    blocks = padded.reshape(padded.shape[0] // factor, factor, padded.shape[1] // factor, factor)
    occupied = (blocks == OCCUPIED).any(axis=(1, 3))
    free = (blocks == FREE).sum(axis=(1, 3)) * 2 >= factor * factor
    out = np.full(occupied.shape, UNKNOWN, dtype=np.uint8)
    out[free] = FREE
    out[occupied] = OCCUPIED
    return out
