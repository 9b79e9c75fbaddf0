"""From an occupancy grid to an exploration goal and a path: crop to the known area,
downsample, inflate, find frontiers, run Dijkstra from the robot, choose a frontier."""

import math
from dataclasses import dataclass, field

import numpy as np

from .costmap import Costmap, inflate
from .frontiers import closed_gaps, find_frontiers, information_gain
from .grid import FREE, UNKNOWN, GridGeometry, classify, downsample, known_window
from .planner import approach_labels, choose_goal, distance_field, extract_path
from .visibility import line_of_sight, sweep_headings


def _drop_cells(labels, frontiers, rows, cols, drop):
    """`labels` without the cells (rows[drop], cols[drop]), and the frontiers left a cell."""
    if not drop.any():
        return labels, frontiers
    labels = labels.copy()
    labels[rows[drop], cols[drop]] = 0
    left = set(np.unique(labels[labels > 0]).tolist())
    return labels, [f for f in frontiers if f.label in left]


def unknown_neighbours(classes, cells):
    """(K, 2) row, col of the UNKNOWN cells among the 8 neighbours of `cells` (N, 2)."""
    cells = np.asarray(cells, dtype=int).reshape(-1, 2)
    h, w = classes.shape
    found = set()
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            rows, cols = cells[:, 0] + dr, cells[:, 1] + dc
            ok = (rows >= 0) & (rows < h) & (cols >= 0) & (cols < w)
            rows, cols = rows[ok], cols[ok]
            hit = classes[rows, cols] == UNKNOWN
            found.update(zip(rows[hit].tolist(), cols[hit].tolist(), strict=True))
    return np.array(sorted(found), dtype=int).reshape(-1, 2)


@dataclass
class PlannerParams:
    plan_resolution: float = 0.10  # m: planning grid cell size (a multiple of the map's)
    robot_radius: float = 0.18  # m: the robot's footprint
    safety_margin: float = 0.05  # m: cells nearer than robot_radius + this are lethal
    inflation_radius: float = 0.30  # m: cost falls to zero this far from obstacles
    cost_scale: float = 3.0  # extra cost per metre at the lethal radius
    min_frontier_size: float = 0.3  # m: smaller frontiers are ignored
    reach_min: float = 0.6  # m: observe a frontier from at least this far (sensor minimum)
    reach_max: float = 2.5  # m: and at most this far, in a straight line through free space
    info_radius: float = 3.0  # m: unknown space this deep behind a frontier counts as gain
    min_gain: float = 1.0  # m^2: frontiers opening onto less unknown space are ignored
    info_weight: float = 1.0  # score bonus (m of path) per m^2 of gain
    info_cap: float = 15.0  # m^2: gain beyond this earns no more bonus
    view_range: float = 4.0  # m: frontier cells this near a view count as seen
    view_half_angle: float = 0.45  # rad: within this bearing of a view's heading
    look_wiggle: float = 0.5  # rad: turn at least this much while looking at a frontier
    # rad: SLAM maps a scan only after the robot turned this much (angularUpdate of
    # gmapping_lite's Turtlebot tuning, 0.436 rad), at a phase the explorer does not know:
    # a look reaches this far past the view that just covers its frontier at each end, so
    # that mapped scans cover all of it (0: the map takes in every scan).
    map_angular_update: float = 0.436
    switch_margin: float = 1.0  # m: keep the current goal unless another scores this much better
    blacklist_radius: float = 0.8  # m
    free_threshold: int = 25
    occupied_threshold: int = 65


@dataclass
class Plan:
    goal: tuple  # (x, y) in the map frame
    path: np.ndarray  # (K, 2) x, y from the robot to the goal
    look_yaws: list  # headings to turn through at the goal to see its frontier
    cost: float  # path cost, m
    frontier_size: float  # m
    gain: float  # m^2 of unknown space behind the frontier
    frontiers_left: int
    kept: bool = False  # the previous goal was kept
    target: tuple = (0.0, 0.0)  # (x, y): middle of the frontier cells seen from the goal
    close: bool = False  # a close approach: the goal stands at the frontier (see plan())
    # (K, 2) x, y of the frontier cells seen from the goal (their mean is `target`)
    seen_points: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))


@dataclass
class PreparedMap:
    geometry: GridGeometry
    classes: np.ndarray
    costmap: object
    labels: np.ndarray
    frontiers: list = field(default_factory=list)
    near: np.ndarray = None  # approach_labels of all frontiers (once per map)
    # Cells the robot's body may fit on (without the safety margin, and allowing for the
    # coarse grid's grown obstacles): where plan() looks when nothing is reachable on
    # `costmap`.
    tight: object = None


class MapPlanner:
    def __init__(self, params=None):
        self.params = params or PlannerParams()
        self.prepared = None
        # The last plan() found no traversable cell near the robot (it brushed a wall or
        # the map moved under it): no plan, but not for want of frontiers.
        self.start_blocked = False

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
            coarse,
            geometry.resolution,
            p.robot_radius + p.safety_margin,
            max(p.inflation_radius, p.robot_radius + p.safety_margin),
            p.cost_scale,
        )
        min_cells = max(1, int(math.ceil(p.min_frontier_size / geometry.resolution)))
        labels, frontiers = find_frontiers(coarse, min_cells)
        cell_area = geometry.resolution**2
        # Unknown space the robot's body cannot reach (beyond gaps narrower than its
        # diameter: the inside of furniture whose face the scan mapped with gaps, the
        # space behind a bed against a wall) is no gain: frontiers opening only onto it
        # attract goals that no look ever clears.
        blocked = closed_gaps(costmap.clearance, geometry.resolution, 2 * p.robot_radius)
        steps = int(round(p.info_radius / geometry.resolution))
        information_gain(coarse, labels, frontiers, steps, blocked)
        dropped = [f.label for f in frontiers if f.gain * cell_area < p.min_gain]
        if dropped:
            labels[np.isin(labels, dropped)] = 0
            frontiers = [f for f in frontiers if f.label not in dropped]
        near = approach_labels(labels, coarse, geometry.resolution, p.reach_max)
        # The coarse grid makes a block occupied if any of its cells is: obstacles grow by
        # up to (factor - 1) map cells, so the body may fit where the coarse clearance
        # exceeds its radius less that.
        body = p.robot_radius - (factor - 1) * resolution
        tight = Costmap(
            (coarse == FREE) & (costmap.clearance > body), costmap.cost, costmap.clearance
        )
        self.prepared = PreparedMap(geometry, coarse, costmap, labels, frontiers, near, tight)
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

    def plan(
        self,
        x,
        y,
        excluded_points=(),
        current_goal=None,
        views=(),
        dead_frontiers=(),
        close_targets=(),
        tight=False,
    ):
        """Plan from (x, y) to the best frontier; None if no frontier is reachable.

        `excluded_points`: blacklisted goals (x, y). `current_goal` (x, y): keep it while
        it still observes a frontier and scores within switch_margin of the best.
        `views` (x, y, yaw): where the robot looked since the map was made; frontier
        cells in view from there count as observed. `dead_frontiers` (x, y): frontier
        cells within blacklist_radius are ignored. `close_targets` (x, y): a frontier with
        cells within blacklist_radius of one was looked at from afar in vain (a grazing
        view along a shadow's edge, an occluded corner): it is approached closely instead,
        from a goal on the frontier, and the look turns towards the unknown cells behind
        it rather than towards the frontier cells. `start_blocked` tells afterwards
        whether None meant no traversable cell near the robot. With nothing reachable, it
        plans once more over the cells the robot's body may fit on (`tight`: without the
        safety margin and the coarse grid's growth of obstacles): the robot may stand in a
        pocket that only those close."""
        self.start_blocked = False
        prep = self.prepared
        if prep is None or not prep.frontiers:
            return None
        p = self.params
        g = prep.geometry
        labels, frontiers = self._unseen(prep.labels, prep.frontiers, views)
        labels, frontiers = self._without(labels, frontiers, dead_frontiers)
        if not frontiers:
            return None
        far_labels, far, close_labels, close = self._split(labels, frontiers, close_targets)
        start = tuple(int(v) for v in g.to_cell(x, y))
        snap = int(math.ceil(0.5 / g.resolution))
        costmap = prep.tight if tight else prep.costmap
        dist = distance_field(costmap, start, g.resolution, snap_cells=snap)
        if dist is None:
            self.start_blocked = True
            return None
        excluded = self._excluded(list(excluded_points))
        # A close approach stands on the frontier: as near its cells as the robot's centre
        # may come to a wall (its radius plus the safety margin) and one cell more, so that
        # a frontier along a wall can be approached too.
        close_reach = p.robot_radius + p.safety_margin + g.resolution
        close_near = None

        def choose_kind(mask, kind_labels, kind_frontiers, reach, near):
            return choose_goal(
                dist,
                prep.classes,
                kind_labels,
                kind_frontiers,
                g.resolution,
                reach=reach,
                info_weight=p.info_weight,
                info_cap=p.info_cap,
                excluded=mask,
                near=near,
            )

        if close:
            close_near = approach_labels(close_labels, prep.classes, g.resolution, close_reach)
            # A frontier nobody can stand on (along a wall, beyond a gap too narrow to pass)
            # is still looked at from afar.
            back = [
                f
                for f in close
                if choose_kind(
                    excluded,
                    np.where(close_labels == f.label, close_labels, 0),
                    [f],
                    (0.0, close_reach),
                    close_near,
                )
                is None
            ]
            if back:
                moved = np.isin(close_labels, [f.label for f in back])
                far_labels = np.where(moved, close_labels, far_labels)
                close_labels = np.where(moved, 0, close_labels)
                far = far + back
                close = [f for f in close if f not in back]

        def choose(mask):
            """The best (choice, close) over both kinds of frontier cells, or None."""
            options = []
            if far:
                # prep.near spreads every frontier's labels; choose_goal skips the ones
                # not in `far` and only tests the cells left in `far_labels`.
                found = choose_kind(mask, far_labels, far, (p.reach_min, p.reach_max), prep.near)
                if found is not None:
                    options.append((found.score, 0, found, False))
            if close:
                found = choose_kind(mask, close_labels, close, (0.0, close_reach), close_near)
                if found is not None:
                    options.append((found.score, 1, found, True))
            return min(options, key=lambda o: o[:2])[2:] if options else None

        chosen = choose(excluded)
        if chosen is None:
            if not tight:
                # The way out of where the robot stands may be closed by the safety margin
                # and the coarse grid alone (it came in that way: pure pursuit cuts
                # corners, the map grew a wall beside the gap); try where the body may fit,
                # at the highest inflation cost. Nothing there either: none left.
                return self.plan(
                    x,
                    y,
                    excluded_points,
                    current_goal,
                    views,
                    dead_frontiers,
                    close_targets,
                    tight=True,
                )
            return None
        kept = False
        if current_goal is not None:
            current = choose(self._all_but(current_goal, excluded))
            if current is not None and current[0].score <= chosen[0].score + p.switch_margin:
                chosen, kept = current, True
        best, is_close = chosen
        cells = extract_path(dist, best.cell)
        xs, ys = g.to_world(cells[:, 0], cells[:, 1])
        path = np.vstack([[x, y], np.column_stack([xs, ys])])
        gx, gy = g.to_world(*best.cell)
        tx, ty = g.to_world(best.seen[:, 0].mean(), best.seen[:, 1].mean())
        seen_points = np.column_stack(g.to_world(best.seen[:, 0], best.seen[:, 1]))
        return Plan(
            (float(gx), float(gy)),
            path,
            self._look_yaws(best, gx, gy, is_close),
            best.cost,
            best.size * g.resolution,
            best.gain,
            len(frontiers),
            kept,
            (float(tx), float(ty)),
            is_close,
            seen_points.reshape(-1, 2),
        )

    def _unseen(self, labels, frontiers, views):
        """Labels and frontiers without the cells in view (range, field of view, line of
        sight) from any of `views`."""
        if not views:
            return labels, frontiers
        prep = self.prepared
        g = prep.geometry
        rows, cols = np.nonzero(labels)
        xs, ys = g.to_world(rows, cols)
        seen = np.zeros(rows.shape, dtype=bool)
        for vx, vy, vyaw in views:
            bearing = np.arctan2(ys - vy, xs - vx) - vyaw
            bearing = np.arctan2(np.sin(bearing), np.cos(bearing))
            in_view = (np.hypot(xs - vx, ys - vy) <= self.params.view_range) & (
                np.abs(bearing) <= self.params.view_half_angle
            )
            idx = np.flatnonzero(in_view & ~seen)
            if idx.size:
                origin = tuple(int(v) for v in g.to_cell(vx, vy))
                targets = np.column_stack([rows[idx], cols[idx]])
                seen[idx[line_of_sight(prep.classes, origin, targets)]] = True
        return _drop_cells(labels, frontiers, rows, cols, seen)

    def _near(self, labels, points):
        """(rows, cols, mask) of the labelled cells and which lie near `points` (x, y)."""
        g = self.prepared.geometry
        rows, cols = np.nonzero(labels)
        xs, ys = g.to_world(rows, cols)
        near = np.zeros(rows.shape, dtype=bool)
        for px, py in points:
            near |= np.hypot(xs - px, ys - py) <= self.params.blacklist_radius
        return rows, cols, near

    def _without(self, labels, frontiers, points):
        """Labels and frontiers without the cells near `points` (x, y)."""
        if not len(points) or not frontiers:
            return labels, frontiers
        return _drop_cells(labels, frontiers, *self._near(labels, points))

    def _split(self, labels, frontiers, points):
        """(labels, frontiers) twice: the frontiers with no cell near `points` (x, y), and
        the ones with some; a frontier is approached closely as a whole, or a view from
        afar would graze along the rest of the same shadow's edge."""
        if not len(points) or not frontiers:
            return labels, frontiers, np.zeros_like(labels), []
        rows, cols, near = self._near(labels, points)
        hit = np.unique(labels[rows[near], cols[near]])
        in_hit = np.isin(labels, hit)
        far_labels = np.where(in_hit, 0, labels)
        close_labels = np.where(in_hit, labels, 0)
        far = [f for f in frontiers if f.label not in hit]
        close = [f for f in frontiers if f.label in hit]
        return far_labels, far, close_labels, close

    def _all_but(self, goal, excluded):
        """An exclusion mask leaving only the 3 x 3 cells around `goal` (x, y)."""
        g = self.prepared.geometry
        row, col = (int(v) for v in g.to_cell(*goal))
        only = np.ones((g.height, g.width), dtype=bool)
        if g.contains(row, col):
            only[max(0, row - 1) : row + 2, max(0, col - 1) : col + 2] = False
        if excluded is not None:
            only |= excluded
        return only

    def _look_yaws(self, choice, gx, gy, close=False):
        """Headings that sweep the sensor over the frontier cells seen from the goal; for
        a close approach, over the unknown cells next to them (the robot stands at the
        frontier, so the bearings of the frontier cells themselves say little)."""
        cells = choice.seen
        if close:
            cells = unknown_neighbours(self.prepared.classes, cells)
            if not len(cells):
                cells = choice.seen
        sx, sy = self.prepared.geometry.to_world(cells[:, 0], cells[:, 1])
        bearings = np.arctan2(sy - gy, sx - gx)
        p = self.params
        h = p.view_half_angle
        headings = sweep_headings(bearings, h, 2 * h, p.map_angular_update, p.look_wiggle)
        if len(headings) == 1 and p.look_wiggle > 0:
            # Turn across the heading: SLAM integrates a scan only after the robot turned
            # angularUpdate (0.436 rad in the Turtlebot tuning), so a look that turns
            # less may never reach the map.
            h = headings[0]
            headings = [h - p.look_wiggle / 2, h + p.look_wiggle / 2]
        return headings

    def known_free_area(self):
        """m^2 of free cells on the planning grid."""
        prep = self.prepared
        if prep is None:
            return 0.0
        return float((prep.classes == FREE).sum()) * prep.geometry.resolution**2
