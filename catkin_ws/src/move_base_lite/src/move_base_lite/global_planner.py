"""Plans on the static map plus what the scan sees: classes from the map, obstacle cells
added, inflated by the robot's radius (explorer.costmap), Dijkstra (explorer.planner)."""

import math
from dataclasses import dataclass

import numpy as np
from explorer.costmap import inflate
from explorer.grid import FREE, OCCUPIED, GridGeometry, classify
from explorer.planner import distance_field, extract_path


def _xy(point):
    """(x, y) to the centimetre; a far-off one (1e300 from a bad goal) in a few digits."""
    return "(" + ", ".join(f"{v:.2f}" if abs(v) < 1e9 else f"{v:.3g}" for v in point[:2]) + ")"


@dataclass
class CostmapParams:
    robot_radius: float = 0.18  # m: Kobuki's footprint
    # Costs fall to zero this far from obstacles (turtlebot_navigation's inflation_radius),
    # so paths keep to the middle of corridors where they can.
    inflation_radius: float = 0.5
    cost_scale: float = 3.0  # explorer.costmap: extra cost per metre at the lethal radius
    occupied_threshold: int = 65  # map values from here on are obstacles (map_server's 0.65)
    free_threshold: int = 25  # and below this free (explorer's classify)


@dataclass
class PlanResult:
    path: np.ndarray | None  # (K, 2) x, y in the map frame, start to goal
    reason: str = ""  # why there is no path (empty when there is one)
    goal_invalid: bool = False  # the goal itself cannot be reached: no retry will help


class GlobalPlanner:
    def __init__(self, values, geometry: GridGeometry, params=None):
        """`values`: the map's OccupancyGrid data as (height, width) int8."""
        self.params = params or CostmapParams()
        if self.params.inflation_radius < self.params.robot_radius:
            raise ValueError("inflation_radius must be >= robot_radius")
        self.geometry = geometry
        self.classes = classify(values, self.params.free_threshold, self.params.occupied_threshold)
        self.static_costmap = self._inflate(self.classes)
        self.costmap = self.static_costmap

    def _inflate(self, classes):
        p = self.params
        return inflate(
            classes, self.geometry.resolution, p.robot_radius, p.inflation_radius, p.cost_scale
        )

    def update_obstacles(self, marked):
        """Rebuild the costmap with the obstacle layer's `marked` cells (bool grid)."""
        classes = self.classes.copy()
        classes[marked] = OCCUPIED
        self.costmap = self._inflate(classes)

    def is_free(self, x, y):
        """Whether the robot's centre may be at (x, y) on the current costmap."""
        row, col = self.geometry.to_cell(x, y)
        return bool(self.geometry.contains(row, col) and self.costmap.traversable[row, col])

    def blocked_ahead(self, path, progress_xy, distance):
        """Whether the path, from the point nearest `progress_xy` on for `distance` metres,
        runs through a cell the robot's centre may not occupy."""
        if path is None or len(path) == 0:
            return False
        d = np.hypot(path[:, 0] - progress_xy[0], path[:, 1] - progress_xy[1])
        start = int(np.argmin(d))
        ahead = path[start:]
        seg = np.r_[0.0, np.cumsum(np.hypot(*np.diff(ahead, axis=0).T))]
        ahead = ahead[seg <= distance]
        # The robot's own surroundings may be inflated (it brushed a wall): check beyond
        # its radius only, or it would never move again.
        far = np.hypot(ahead[:, 0] - progress_xy[0], ahead[:, 1] - progress_xy[1])
        ahead = ahead[far > self.params.inflation_radius]
        if len(ahead) == 0:
            return False
        rows, cols = self.geometry.to_cell(ahead[:, 0], ahead[:, 1])
        ok = self.geometry.contains(rows, cols)
        return bool(not ok.all() or not self.costmap.traversable[rows, cols].all())

    def plan(self, start, goal):
        """A PlanResult from `start` (x, y) to `goal` (x, y) in the map frame."""
        g = self.geometry
        # Far beyond any map (1e9 m), or NaN: outside, said before the cell index overflows.
        far = not all(abs(v) < 1e9 for v in goal[:2])
        goal_cell = (-1, -1) if far else tuple(int(v) for v in g.to_cell(*goal))
        if not g.contains(*goal_cell):
            return PlanResult(None, f"goal {_xy(goal)} is outside the map", True)
        if self.static_costmap.traversable[goal_cell] and not self.costmap.traversable[goal_cell]:
            # Only the scan's obstacles cover it: they may be gone (or misplaced by a poor
            # pose) next time, so this is worth a recovery and a retry, not an abort.
            return PlanResult(None, f"goal {_xy(goal)} is blocked by an obstacle the scan sees")
        if not self.costmap.traversable[goal_cell]:
            clearance = float(self.costmap.clearance[goal_cell])
            why = (
                "unknown space"
                if self.classes[goal_cell] != FREE and clearance > self.params.robot_radius
                else f"an obstacle or closer than the robot radius "
                f"({self.params.robot_radius:.2f} m) to one"
            )
            return PlanResult(None, f"goal {_xy(goal)} is in {why}", True)
        start_cell = tuple(int(v) for v in g.to_cell(*start))
        snap = max(1, math.ceil(self.params.inflation_radius / g.resolution))
        field = distance_field(self.costmap, start_cell, g.resolution, snap_cells=snap)
        if field is None:
            return PlanResult(None, f"the robot at {_xy(start)} is not in free space")
        cells = extract_path(field, goal_cell)
        if cells is None:
            return PlanResult(
                None,
                f"no path from {_xy(start)} to {_xy(goal)}",
            )
        xs, ys = g.to_world(cells[:, 0], cells[:, 1])
        path = np.column_stack([xs, ys])
        path[-1] = goal  # end exactly on the goal, not on its cell's centre
        return PlanResult(path)
