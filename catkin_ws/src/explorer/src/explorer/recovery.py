"""Getting unstuck: notice when commanded motion makes no progress, then back up and turn."""

import math
from collections import deque
from dataclasses import dataclass


class StuckMonitor:
    """Stuck = over the last `window` seconds of trying to move, the robot moved less than
    `min_motion` metres and turned less than `min_turn` radians."""

    def __init__(self, window=6.0, min_motion=0.10, min_turn=0.5):
        self.window = window
        self.min_motion = min_motion
        self.min_turn = min_turn
        self.samples = deque()

    def reset(self):
        self.samples.clear()

    def update(self, now, x, y, yaw):
        """Add a pose while the robot is trying to move; True when stuck."""
        self.samples.append((now, x, y, yaw))
        while self.samples and now - self.samples[0][0] > self.window:
            self.samples.popleft()
        if now - self.samples[0][0] < 0.9 * self.window:
            return False
        _, x0, y0, _ = self.samples[0]
        moved = max(math.hypot(sx - x0, sy - y0) for _, sx, sy, _ in self.samples)
        turned = 0.0
        for a, b in zip(self.samples, list(self.samples)[1:], strict=False):
            turned += abs(math.atan2(math.sin(b[3] - a[3]), math.cos(b[3] - a[3])))
        return moved < self.min_motion and turned < self.min_turn


@dataclass
class RecoveryParams:
    backup_speed: float = 0.1  # m/s
    backup_time: float = 1.5  # s
    turn_speed: float = 0.8  # rad/s
    turn_time: float = 2.0  # s


class Recovery:
    """A timed manoeuvre: back up, then turn in place towards `turn_sign` (+1 left)."""

    def __init__(self, start, turn_sign=1.0, params=None):
        self.start = start
        self.turn_sign = 1.0 if turn_sign >= 0 else -1.0
        self.params = params or RecoveryParams()

    def command(self, now):
        """(linear, angular, finished)."""
        p = self.params
        elapsed = now - self.start
        if elapsed < p.backup_time:
            return -p.backup_speed, 0.0, False
        if elapsed < p.backup_time + p.turn_time:
            return 0.0, self.turn_sign * p.turn_speed, False
        return 0.0, 0.0, True


class Blacklist:
    """Goal points to avoid for a while (unreachable or unobservable frontiers)."""

    def __init__(self, radius=0.5, timeout=60.0):
        self.radius = radius
        self.timeout = timeout
        self.entries = []  # (x, y, expiry)

    def add(self, x, y, now):
        self.entries.append((x, y, now + self.timeout))

    def active(self, now):
        self.entries = [e for e in self.entries if e[2] > now]
        return [(x, y) for x, y, _ in self.entries]

    def clear(self):
        self.entries = []
