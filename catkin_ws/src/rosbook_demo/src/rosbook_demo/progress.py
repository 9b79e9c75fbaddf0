"""Progress lines for long simulated runs: simulated time, speed-up, distance, map size."""

import math


class ProgressMeter:
    def __init__(self, sim_seconds, wall_start, sim_start):
        self.sim_seconds = sim_seconds
        self.wall_start = wall_start
        self.sim_start = sim_start
        self.distance = 0.0
        self._last_xy = None

    def add_position(self, x, y):
        if not (math.isfinite(x) and math.isfinite(y)):
            return
        if self._last_xy is not None:
            self.distance += math.hypot(x - self._last_xy[0], y - self._last_xy[1])
        self._last_xy = (x, y)

    def line(self, sim_now, wall_now, known_area_m2=None):
        elapsed_sim = max(sim_now - self.sim_start, 0.0)
        elapsed_wall = max(wall_now - self.wall_start, 1e-9)
        fraction = min(elapsed_sim / self.sim_seconds, 1.0) if self.sim_seconds > 0 else 0.0
        bar = "#" * int(round(20 * fraction))
        parts = [
            f"[{bar:<20}] {elapsed_sim:6.0f}/{self.sim_seconds:.0f} s simulated",
            f"{elapsed_sim / elapsed_wall:5.1f}x real time",
            f"travelled {self.distance:6.1f} m",
        ]
        if known_area_m2 is not None:
            parts.append(f"map {known_area_m2:6.1f} m² known")
        return " | ".join(parts)


def known_area(grid):
    """Area (m²) of the cells of an OccupancyGrid that are not unknown (-1)."""
    known = sum(1 for v in grid.data if v != -1)
    return known * grid.info.resolution**2
