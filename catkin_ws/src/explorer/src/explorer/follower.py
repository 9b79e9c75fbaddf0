"""Path following for a differential-drive base: pure pursuit, turning in place first when
the heading error is large, slowing for the goal and for obstacles seen ahead."""

import math
from dataclasses import dataclass

import numpy as np


def wrap(angle):
    """Angle in (-pi, pi]."""
    return math.atan2(math.sin(angle), math.cos(angle))


@dataclass
class FollowerParams:
    max_linear: float = 0.35  # m/s
    max_angular: float = 1.0  # rad/s
    lookahead: float = 0.5  # m
    rotate_threshold: float = 0.8  # rad: turn in place above this heading error
    goal_tolerance: float = 0.25  # m
    heading_gain: float = 2.0  # rad/s per rad when turning in place
    goal_slowdown: float = 0.8  # m/s per metre to the goal
    min_linear: float = 0.05  # m/s: the slowest useful forward speed
    # Share of max_linear given up at rotate_threshold (linearly in the heading error).
    # 0: none; the speed is then bounded by the turning rate alone (max_angular over the
    # pure-pursuit arc's curvature), which already slows the sharp turns.
    heading_slowdown: float = 0.0


class PurePursuit:
    """Follows one path; call `command` each control cycle with the robot pose."""

    def __init__(self, path, params=None):
        path = np.asarray(path, dtype=float).reshape(-1, 2)
        if len(path) == 0:
            raise ValueError("empty path")
        self.path = path
        self.params = params or FollowerParams()
        self.progress = 0  # index of the path point closest to the robot, never decreases

    @property
    def goal(self):
        return self.path[-1]

    def distance_to_goal(self, x, y):
        return math.hypot(self.goal[0] - x, self.goal[1] - y)

    def _lookahead_point(self, x, y):
        p = self.params
        # Advance progress to the closest point within a short window ahead (paths may
        # loop near themselves; a window keeps us from skipping ahead).
        window = self.path[self.progress : self.progress + 40]
        d = np.hypot(window[:, 0] - x, window[:, 1] - y)
        self.progress += int(np.argmin(d))
        ahead = self.path[self.progress :]
        d = np.hypot(ahead[:, 0] - x, ahead[:, 1] - y)
        beyond = np.flatnonzero(d >= p.lookahead)
        return ahead[beyond[0]] if beyond.size else ahead[-1]

    def command(self, x, y, yaw, clearance=math.inf):
        """(linear, angular, arrived). `clearance`: free distance ahead (m) beyond the
        stopping distance; forward speed is limited so the robot can stop in it."""
        p = self.params
        if self.distance_to_goal(x, y) <= p.goal_tolerance:
            return 0.0, 0.0, True
        tx, ty = self._lookahead_point(x, y)
        alpha = wrap(math.atan2(ty - y, tx - x) - yaw)
        if abs(alpha) > p.rotate_threshold:
            return 0.0, _turn(alpha, p), False
        distance = max(math.hypot(tx - x, ty - y), 1e-3)
        curvature = 2.0 * math.sin(alpha) / distance
        linear = p.max_linear * (1.0 - p.heading_slowdown * abs(alpha) / p.rotate_threshold)
        linear = min(linear, p.min_linear + p.goal_slowdown * self.distance_to_goal(x, y))
        linear = min(linear, max(0.0, clearance))
        angular = linear * curvature
        if abs(angular) > p.max_angular:
            linear *= p.max_angular / abs(angular)
            angular = math.copysign(p.max_angular, angular)
        if linear < 1e-3:
            # Blocked ahead or no speed left: line up with the path instead.
            return 0.0, _turn(alpha, p) if abs(alpha) > 0.05 else 0.0, False
        return linear, angular, False


def _turn(error, params):
    rate = min(params.max_angular, max(0.3, params.heading_gain * abs(error)))
    return math.copysign(rate, error)


def turn_towards(yaw, target_yaw, params=None, tolerance=0.1, passing=False):
    """(angular, done) to turn in place to `target_yaw`. `passing`: the turn goes on
    beyond it in the same direction (a sweep through several headings), so it keeps the
    full turning rate instead of slowing down to stop there."""
    params = params or FollowerParams()
    error = wrap(target_yaw - yaw)
    if abs(error) <= tolerance:
        return 0.0, True
    if passing:
        return math.copysign(params.max_angular, error), False
    return _turn(error, params), False
