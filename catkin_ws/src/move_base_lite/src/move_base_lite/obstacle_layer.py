"""What the scan sees that the map lacks: a grid over the map marked where beams end and
cleared along the beams, as costmap_2d's obstacle layer marks and clears."""

import numpy as np
from explorer.grid import GridGeometry


def scan_endpoints(ranges, angle_min, angle_increment, range_min, range_max, sensor_pose):
    """Beam ends in the map frame: ((K, 2) hits, (M, 2) free-space ends of no-return beams,
    and the sensor's (x, y)). `sensor_pose` is the sensor's (x, y, yaw) in the map frame.
    NaN readings carry nothing; +inf and readings at range_max mean free up to range_max."""
    r = np.asarray(ranges, dtype=float)
    angles = angle_min + angle_increment * np.arange(r.size) + sensor_pose[2]
    hit = np.isfinite(r) & (r >= range_min) & (r < range_max)
    clear = np.isposinf(r) | (np.isfinite(r) & (r >= range_max))
    origin = np.array(sensor_pose[:2], dtype=float)

    def ends(mask, dist):
        return origin + np.column_stack([dist * np.cos(angles[mask]), dist * np.sin(angles[mask])])

    return ends(hit, r[hit]), ends(clear, np.full(clear.sum(), range_max)), origin


class ObstacleLayer:
    """Cells marked as obstacles by recent scans, over the geometry of the static map."""

    def __init__(self, geometry: GridGeometry, max_range=4.0):
        """`max_range`: marks and clears only within this distance of the sensor (far
        readings of a depth camera are noisy, and far obstacles do not matter yet)."""
        self.geometry = geometry
        self.max_range = max_range
        self.marked = np.zeros((geometry.height, geometry.width), dtype=bool)

    def clear_all(self):
        self.marked[:] = False

    def update(self, hits, free_ends, origin):
        g = self.geometry
        self._clear_rays(np.vstack([hits, free_ends]), origin, keep_last=len(hits))
        if len(hits):
            near = np.hypot(*(hits - origin).T) <= self.max_range
            rows, cols = g.to_cell(hits[near, 0], hits[near, 1])
            ok = g.contains(rows, cols)
            self.marked[rows[ok], cols[ok]] = True

    def _clear_rays(self, ends, origin, keep_last):
        """Clear the cells each beam passed through, up to max_range and short of its end
        (half a cell back, so a hit cell is not cleared by its own beam)."""
        if len(ends) == 0:
            return
        g = self.geometry
        vec = ends - origin
        length = np.hypot(vec[:, 0], vec[:, 1])
        reach = np.minimum(length - g.resolution, self.max_range)
        steps = np.arange(0.0, self.max_range, g.resolution / 2)
        frac = steps[None, :] / np.maximum(length, 1e-9)[:, None]
        inside = steps[None, :] <= reach[:, None]
        xs = origin[0] + frac * vec[:, 0:1]
        ys = origin[1] + frac * vec[:, 1:2]
        rows, cols = g.to_cell(xs[inside], ys[inside])
        ok = g.contains(rows, cols)
        self.marked[rows[ok], cols[ok]] = False
