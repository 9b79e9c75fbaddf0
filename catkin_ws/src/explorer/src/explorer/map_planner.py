"""From an occupancy grid to an exploration goal and a path: crop to the known area,
downsample, inflate, find frontiers, run Dijkstra from the robot, choose a frontier."""

import math
from dataclasses import dataclass, field

import numpy as np

from .costmap import inflate
from .frontiers import find_frontiers, information_gain
from .grid import FREE, GridGeometry, classify, downsample, known_window
from .planner import choose_goal, distance_field, extract_path


@dataclass
class PlannerParams:
    plan_resolution: float = 0.10  # m: planning grid cell size (a multiple of the map's)
    robot_radius: float = 0.18  # m: cells nearer an obstacle are lethal
    inflation_radius: float = 0.30  # m: cost falls to zero this far from obstacles
    cost_scale: float = 3.0  # extra cost per metre at the lethal radius
    min_frontier_size: float = 0.3  # m: smaller frontiers are ignored
    reach_min: float = 0.6  # m: observe a frontier from at least this far (sensor minimum)
    reach_max: float = 1.2  # m: and at most this far (through free space)
    info_radius: float = 1.5  # m: unknown space this deep behind a frontier counts as gain
    min_gain: float = 0.2  # m^2: frontiers opening onto less unknown space are ignored
    info_weight: float = 0.5  # score bonus (m of path) per m^2 of gain
    info_cap: float = 8.0  # m^2: gain beyond this earns no more bonus
    switch_margin: float = 1.0  # m: keep the current goal unless another scores this much better
    blacklist_radius: float = 0.5  # m
    free_threshold: int = 25
    occupied_threshold: int = 65


@dataclass
class Plan:
    goal: tuple  # (x, y) in the map frame
    path: np.ndarray  # (K, 2) x, y from the robot to the goal
    look_yaw: float  # heading that faces the frontier from the goal
    cost: float  # path cost, m
    frontier_size: float  # m
    gain: float  # m^2 of unknown space behind the frontier
    frontiers_left: int
    kept: bool = False  # the previous goal was kept


@dataclass
class PreparedMap:
    geometry: GridGeometry
    classes: np.ndarray
    costmap: object
    labels: np.ndarray
    frontiers: list = field(default_factory=list)


class MapPlanner:
    def __init__(self, params=None):
        self.params = params or PlannerParams()
        self.prepared = None

    def set_map(self, data, resolution, origin_x, origin_y):
        """data: (height, width) OccupancyGrid values. Returns False if nothing is known."""
        p = self.params
        classes = classify(data, p.free_threshold, p.occupied_threshold)
        factor = max(1, int(round(p.plan_resolution / resolution)))
        margin = 2 * factor
        window = known_window(classes, margin)
        if window is None:
            self.prepared = None
            return False
        r0, c0, r1, c1 = window
        height, width = classes.shape
        full = GridGeometry(resolution, origin_x, origin_y, width, height)
        coarse = downsample(classes[r0:r1, c0:c1], factor)
        geometry = full.sub(r0, c0, coarse.shape[0], coarse.shape[1], factor)
        costmap = inflate(
            coarse, geometry.resolution, p.robot_radius, p.inflation_radius, p.cost_scale
        )
        min_cells = max(1, int(math.ceil(p.min_frontier_size / geometry.resolution)))
        labels, frontiers = find_frontiers(coarse, min_cells)
        cell_area = geometry.resolution**2
        information_gain(coarse, labels, frontiers, int(round(p.info_radius / geometry.resolution)))
        dropped = [f.label for f in frontiers if f.gain * cell_area < p.min_gain]
        if dropped:
            labels[np.isin(labels, dropped)] = 0
            frontiers = [f for f in frontiers if f.label not in dropped]
        self.prepared = PreparedMap(geometry, coarse, costmap, labels, frontiers)
        return True

    @property
    def frontier_count(self):
        return len(self.prepared.frontiers) if self.prepared else 0

    def _excluded(self, points):
        g = self.prepared.geometry
        if not points:
            return None
        rows, cols = np.mgrid[0 : g.height, 0 : g.width]
        xs, ys = g.to_world(rows, cols)
        mask = np.zeros((g.height, g.width), dtype=bool)
        r2 = self.params.blacklist_radius**2
        for x, y in points:
            mask |= (xs - x) ** 2 + (ys - y) ** 2 <= r2
        return mask

    def plan(self, x, y, excluded_points=(), current_goal=None):
        """Plan from (x, y) to the best frontier; None if no frontier is reachable.
        With `current_goal` (x, y), keep it while it still observes a frontier and scores
        within switch_margin of the best."""
        prep = self.prepared
        if prep is None or not prep.frontiers:
            return None
        p = self.params
        g = prep.geometry
        start = tuple(int(v) for v in g.to_cell(x, y))
        snap = int(math.ceil(0.5 / g.resolution))
        dist = distance_field(prep.costmap, start, g.resolution, snap_cells=snap)
        if dist is None:
            return None
        excluded = self._excluded(list(excluded_points))
        kwargs = dict(
            reach=(p.reach_min, p.reach_max), info_weight=p.info_weight, info_cap=p.info_cap
        )
        best = choose_goal(
            dist,
            prep.classes,
            prep.labels,
            prep.frontiers,
            g.resolution,
            excluded=excluded,
            **kwargs,
        )
        if best is None:
            return None
        kept = False
        if current_goal is not None:
            current = self._goal_score(dist, current_goal, excluded, **kwargs)
            if current is not None and current.score <= best.score + p.switch_margin:
                best, kept = current, True
        cells = extract_path(dist, best.cell)
        xs, ys = g.to_world(cells[:, 0], cells[:, 1])
        path = np.column_stack([xs, ys])
        path = np.vstack([[x, y], path])
        gx, gy = g.to_world(*best.cell)
        look = self._look_yaw(best, gx, gy)
        return Plan(
            (float(gx), float(gy)),
            path,
            look,
            best.cost,
            best.size * g.resolution,
            best.gain,
            len(prep.frontiers),
            kept,
        )

    def _look_yaw(self, choice, gx, gy):
        """Heading from the goal to the part of its frontier within view (3 m)."""
        prep = self.prepared
        g = prep.geometry
        rows, cols = np.nonzero(prep.labels == choice.label)
        xs, ys = g.to_world(rows, cols)
        near = np.hypot(xs - gx, ys - gy) <= 3.0
        if near.any():
            xs, ys = xs[near], ys[near]
        dx, dy = float(xs.mean() - gx), float(ys.mean() - gy)
        return math.atan2(dy, dx) if math.hypot(dx, dy) > 1e-6 else 0.0

    def _goal_score(self, dist, goal, excluded, **kwargs):
        """The current goal re-scored on the new map, if it still observes a frontier."""
        prep = self.prepared
        g = prep.geometry
        row, col = (int(v) for v in g.to_cell(*goal))
        if not g.contains(row, col):
            return None
        # Reuse choose_goal restricted to the goal cell's neighbourhood (3 x 3).
        only = np.ones((g.height, g.width), dtype=bool)
        only[max(0, row - 1) : row + 2, max(0, col - 1) : col + 2] = False
        if excluded is not None:
            only |= excluded
        return choose_goal(
            dist, prep.classes, prep.labels, prep.frontiers, g.resolution, excluded=only, **kwargs
        )

    def known_free_area(self):
        """m^2 of free cells on the planning grid."""
        prep = self.prepared
        if prep is None:
            return 0.0
        return float((prep.classes == FREE).sum()) * prep.geometry.resolution**2
