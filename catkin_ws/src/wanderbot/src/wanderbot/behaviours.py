"""Timed behaviours of chapter 7 as plain state machines: time is passed in (seconds), so
they run the same under wall time, sim time and in unit tests."""

import math


class TrafficLight:
    """red_light_green_light: alternate `period` seconds of driving and of stopping.

    Starts red; the first update turns green (the light is due to change at start), then the
    light flips every `period` seconds. The book's listing compares the other way round
    (`light_change_time > now`), so it never changes.
    """

    def __init__(self, start_time, period=3.0):
        self.period = float(period)
        self.driving = False
        self.change_time = float(start_time)
        self.last_now = float(start_time)

    def update(self, now):
        if now < self.last_now:
            # Time jumped back (simulator restarted, `rosbag play --loop`): the pending change
            # is in the new clock's far future; time the current phase from now instead.
            self.change_time = now + self.period
        self.last_now = now
        if now >= self.change_time:
            self.driving = not self.driving
            self.change_time = now + self.period
        return self.driving


class Wanderer:
    """wander: drive until an obstacle is closer than `min_range` or `drive_time` passes,
    then spin in place for `spin_time`, and repeat. A spin that ends facing an obstacle is
    followed by another spin (the book drives for one cycle, then turns again).

    `range_ahead` None means the scan said nothing usable (all NaN, or no scan yet): the
    robot does not drive blind into it, it treats it as blocked.
    """

    DRIVE = "drive"
    SPIN = "spin"

    def __init__(self, start_time, min_range=0.8, drive_time=30.0, spin_time=5.0):
        self.min_range = float(min_range)
        self.drive_time = float(drive_time)
        self.spin_time = float(spin_time)
        self.state = self.DRIVE
        self.state_change_time = float(start_time) + self.drive_time
        self.last_now = float(start_time)

    def blocked(self, range_ahead):
        return range_ahead is None or math.isnan(range_ahead) or range_ahead < self.min_range

    def update(self, now, range_ahead):
        if now < self.last_now:
            # Time jumped back (simulator restarted, `rosbag play --loop`): time the current
            # state afresh from now rather than waiting for the old clock's deadline.
            self.state_change_time = now + (
                self.drive_time if self.state == self.DRIVE else self.spin_time
            )
        self.last_now = now
        if self.state == self.DRIVE:
            if self.blocked(range_ahead) or now > self.state_change_time:
                self.state = self.SPIN
                self.state_change_time = now + self.spin_time
        elif now > self.state_change_time:
            if self.blocked(range_ahead):
                # Still blocked: another spin, rather than one forward command into it.
                self.state_change_time = now + self.spin_time
            else:
                self.state = self.DRIVE
                self.state_change_time = now + self.drive_time
        return self.state

    def command(self, forward_speed, turn_speed):
        """(linear x, angular z) for the current state."""
        if self.state == self.DRIVE:
            return (float(forward_speed), 0.0)
        return (0.0, float(turn_speed))
