"""A ROS-free stand-in for the simulator and SLAM, for testing the exploring behaviour on
a world map: a grid world from a PGM, a Kinect-like ray fan, a perfect-pose mapper and a
differential-drive robot moved by the explorer's own commands."""

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from map_server import pgm
from scipy import ndimage

REPO = Path(__file__).resolve().parents[2]
WORLDS = REPO / "catkin_ws" / "src" / "bullet_turtlebot" / "worlds"
CAMERA_X = -0.087  # camera_depth_frame behind base_footprint (URDF)
KINECT_FOV = math.radians(58)


@dataclass(frozen=True)
class Laser:
    """A ray fan and what the mapper makes of it: `map_urange` clips the free space a beam
    clears (gmapping's maxUrange), returns beyond `map_range` are dropped (maxRange)."""

    fov: float = KINECT_FOV
    beams: int = 80
    range_max: float = 8.0
    map_range: float = math.inf
    map_urange: float = 8.0


KINECT = Laser()
# bench_slam_worlds' wide laser (270 deg, 30 m) under live SLAM's Turtlebot tuning
# (maxRange 8 m, maxUrange 6 m), and under SLAM ranges that match it.
WIDE_TURTLEBOT_SLAM = Laser(math.radians(270), 360, 30.0, 8.0, 6.0)
WIDE = Laser(math.radians(270), 360, 30.0, 30.0, 30.0)


def read_pgm(path):
    """A PGM as a uint8 array, row 0 = top of the image (map_server's reader)."""
    pixels, _ = pgm.read_pgm(path)
    return pixels


def read_map_yaml(path):
    """(resolution, origin x, origin y, image path) of a map_server YAML (flat keys)."""
    values = {}
    for line in Path(path).read_text().splitlines():
        line = line.split("#", 1)[0]
        if ":" in line and not line.startswith(" "):
            key, value = line.split(":", 1)
            values[key.strip()] = value.strip()
    origin = [float(v) for v in values["origin"].strip("[]").split(",")]
    return float(values["resolution"]), origin[0], origin[1], Path(path).parent / values["image"]


@dataclass
class GridWorld:
    """Occupied cells (row 0 at origin_y, as OccupancyGrid) in the world frame."""

    occupied: np.ndarray
    resolution: float
    origin_x: float
    origin_y: float

    @classmethod
    def from_yaml(cls, path):
        resolution, ox, oy, image = read_map_yaml(path)
        pixels = np.flipud(read_pgm(image))
        return cls(pixels < 128, resolution, ox, oy)

    def cell(self, x, y):
        col = np.floor((np.asarray(x) - self.origin_x) / self.resolution).astype(int)
        row = np.floor((np.asarray(y) - self.origin_y) / self.resolution).astype(int)
        return row, col

    def blocked(self, x, y):
        row, col = self.cell(x, y)
        h, w = self.occupied.shape
        outside = (row < 0) | (row >= h) | (col < 0) | (col >= w)
        return outside | self.occupied[np.clip(row, 0, h - 1), np.clip(col, 0, w - 1)]

    def clearance(self):
        """Metres from each cell centre to the nearest occupied cell's edge."""
        return (
            ndimage.distance_transform_edt(~self.occupied) * self.resolution - self.resolution / 2
        )

    def free_region(self, x, y):
        """Free cells connected to (x, y): the space a mapper can discover from there."""
        labels, _ = ndimage.label(~self.occupied)
        row, col = self.cell(x, y)
        return labels == labels[row, col]


def cast_fan(world, x, y, yaw, fov=KINECT_FOV, beams=80, range_min=0.45, range_max=8.0):
    """(angles, ranges) of a scan from a sensor at (x, y, yaw); REP 117 special values:
    +inf for nothing within range_max, -inf for a hit closer than range_min."""
    angles = np.linspace(-fov / 2, fov / 2, beams)
    step = world.resolution / 2
    t = np.arange(step, range_max + step, step)
    xs = x + np.cos(yaw + angles)[:, None] * t[None, :]
    ys = y + np.sin(yaw + angles)[:, None] * t[None, :]
    hit = world.blocked(xs, ys)
    first = np.where(hit.any(axis=1), hit.argmax(axis=1), -1)
    ranges = np.where(first >= 0, t[np.maximum(first, 0)], np.inf)
    ranges[(first >= 0) & (ranges < range_min)] = -np.inf
    return angles, ranges


class Mapper:
    """Perfect-pose occupancy mapping on the world's grid: cells along each beam become
    free, the beam's end becomes occupied. Publishes -1/0/100 like gmapping."""

    def __init__(self, world):
        self.world = world
        self.free = np.zeros(world.occupied.shape, dtype=bool)
        self.hit = np.zeros(world.occupied.shape, dtype=bool)

    def integrate(self, x, y, yaw, angles, ranges, range_max=8.0, max_range=math.inf):
        """Add one scan taken at (x, y, yaw); NaN and -inf beams carry no information, nor
        do returns beyond `max_range`; a beam clears free space up to `range_max`."""
        angles = np.asarray(angles, dtype=float)
        ranges = np.asarray(ranges, dtype=float)
        use = ~np.isnan(ranges) & ~np.isneginf(ranges)
        use &= ~(np.isfinite(ranges) & (ranges > max_range))
        angles, ranges = angles[use], ranges[use]
        reach = np.where(np.isfinite(ranges), np.minimum(ranges, range_max), range_max)
        step = self.world.resolution / 2
        t = np.arange(0.0, range_max, step)
        cos, sin = np.cos(yaw + angles)[:, None], np.sin(yaw + angles)[:, None]
        along = t[None, :] < reach[:, None] - step
        rows, cols = self.world.cell(x + cos * t, y + sin * t)
        self._mark(self.free, rows[along], cols[along])
        ends = np.isfinite(ranges) & (ranges <= range_max + 1e-6)
        rows, cols = self.world.cell(
            x + cos[ends, 0] * ranges[ends], y + sin[ends, 0] * ranges[ends]
        )
        self._mark(self.hit, rows, cols)

    @staticmethod
    def _mark(grid, rows, cols):
        h, w = grid.shape
        ok = (rows >= 0) & (rows < h) & (cols >= 0) & (cols < w)
        grid[rows[ok], cols[ok]] = True

    def occupancy(self):
        data = np.full(self.free.shape, -1, dtype=np.int8)
        data[self.free] = 0
        data[self.hit] = 100
        return data

    def known(self):
        return self.free | self.hit


@dataclass
class RunResult:
    coverage: float  # share of the reachable free area known
    sim_time: float
    travelled: float
    collisions: int  # control steps (dt) the robot pushed against an obstacle (bumper)
    done: bool
    goals: int
    coverage_at: dict  # sim seconds -> coverage


class KinematicBase:
    """The robot of a run in `world`: its pose, the camera's scans mapped by a Mapper (a
    scan integrated only after `update` = (metres, radians) of motion, as gmapping does)
    and differential-drive motion that the bumper stops at `robot_radius` from a wall."""

    def __init__(self, world, start, robot_radius, update, laser=KINECT):
        self.world = world
        self.laser = laser
        self.x, self.y, self.yaw = start
        self.robot_radius = robot_radius
        self.update = update
        self.mapper = Mapper(world)
        self.reachable = world.free_region(self.x, self.y)
        self.travelled, self.collisions = 0.0, 0
        self._clearance_grid = world.clearance()
        self._last_update = (self.x, self.y, self.yaw, True)

    def scan(self):
        """(clearance ahead, whether the mapper integrated it) of one scan from here."""
        x, y, yaw = self.x, self.y, self.yaw
        sx, sy = x + CAMERA_X * math.cos(yaw), y + CAMERA_X * math.sin(yaw)
        laser = self.laser
        angles, ranges = cast_fan(
            self.world, sx, sy, yaw, laser.fov, laser.beams, range_max=laser.range_max
        )
        moved = math.hypot(x - self._last_update[0], y - self._last_update[1])
        turned = abs(math.remainder(yaw - self._last_update[2], 2 * math.pi))
        integrated = moved >= self.update[0] or turned >= self.update[1] or self._last_update[3]
        if integrated:
            self.mapper.integrate(
                sx, sy, yaw, angles, ranges, laser.map_urange, max_range=laser.map_range
            )
            self._last_update = (x, y, yaw, False)
        return _clearance(angles, ranges, self.robot_radius, laser.range_max), integrated

    def drive(self, linear, angular, dt, explorer, now):
        """Move for `dt` at (linear, angular); into a wall, the base stays and the explorer
        hears the bumper."""
        nx = self.x + linear * math.cos(self.yaw) * dt
        ny = self.y + linear * math.sin(self.yaw) * dt
        row, col = self.world.cell(nx, ny)
        if self._clearance_grid[row, col] < self.robot_radius:
            self.collisions += 1
            explorer.bumped(now)
        else:
            self.travelled += math.hypot(nx - self.x, ny - self.y)
            self.x, self.y = nx, ny
        turned = self.yaw + angular * dt
        self.yaw = math.atan2(math.sin(turned), math.cos(turned))

    def coverage(self):
        return _coverage(self.mapper, self.reachable)


def explore(
    world,
    start,
    seconds,
    explorer,
    planner,
    dt=0.1,
    map_period=2.0,
    scan_period=0.2,
    robot_radius=0.18,
    checkpoints=(100, 200, 300, 400, 600),
    update=(0.5, 0.436),
):
    """Drive `explorer` (exploration.Explorer) with `planner` (map_planner.MapPlanner) in
    `world` from `start` (x, y, yaw) for `seconds` of simulated time. The map integrates
    a scan only after `update` = (metres, radians) of motion, as gmapping does."""
    robot = KinematicBase(world, start, robot_radius, update)
    next_map = next_scan = 0.0
    map_stamp = None
    ahead = math.inf
    coverage_at = {}
    now = 0.0
    while now < seconds:
        if now >= next_scan:
            ahead, _ = robot.scan()
            next_scan += scan_period
        if now >= next_map:
            planner.set_map(
                robot.mapper.occupancy(), world.resolution, world.origin_x, world.origin_y
            )
            map_stamp = now
            next_map += map_period
        if explorer.wants_plan(now, map_stamp):
            plan = planner.plan(
                robot.x,
                robot.y,
                explorer.excluded_points(now),
                explorer.current_goal,
                explorer.pending_views(map_stamp),
                explorer.excluded_frontiers(now),
            )
            explorer.accept_plan(plan, now, map_stamp)
        linear, angular = explorer.control(now, robot.x, robot.y, robot.yaw, ahead)
        robot.drive(linear, angular, dt, explorer, now)
        now += dt
        for mark in checkpoints:
            if mark not in coverage_at and now >= mark:
                coverage_at[mark] = robot.coverage()
        if explorer.done:
            break
    return RunResult(
        robot.coverage(),
        now,
        robot.travelled,
        robot.collisions,
        explorer.done,
        explorer.goals_reached,
        coverage_at,
    )


def _clearance(angles, ranges, half_width, range_max=8.0):
    from explorer.scan_safety import clearance_ahead

    increment = angles[1] - angles[0]
    return clearance_ahead(
        ranges, angles[0], increment, 0.45, range_max, half_width + 0.04, CAMERA_X
    )


def _coverage(mapper, reachable):
    return float((mapper.known() & reachable).sum()) / float(reachable.sum())
