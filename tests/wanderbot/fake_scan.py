#!/usr/bin/python3
"""Publish synthetic LaserScans on `scan` at 10 Hz following a schedule: PATTERN@SECONDS ...
(seconds from the first subscriber). Patterns: clear (NaN and +inf only), near (0.5 m in one
beam, NaN elsewhere), minus (one -inf beam), allnan, far (2.0 m everywhere).
Here (not lockstep_scans) PATTERN@/ABS/PATH is due once that file exists: a test moves the
schedule on when it has seen what it needs, whatever the load."""

import math
import os
import sys
import time

import rospy
from sensor_msgs.msg import LaserScan

N = 640


def ranges(pattern):
    nan, inf = math.nan, math.inf
    if pattern == "clear":
        return [nan if i % 2 else inf for i in range(N)]
    if pattern == "near":
        return [0.5 if i == 100 else nan for i in range(N)]
    if pattern == "minus":
        return [-inf if i == 500 else inf for i in range(N)]
    if pattern == "allnan":
        return [nan] * N
    if pattern == "far":
        return [2.0] * N
    raise SystemExit(f"fake_scan: unknown pattern {pattern}")


def parse_plan(items):
    """[(seconds, pattern), ...] of PATTERN@SECONDS items; an unknown pattern exits here."""
    plan = []
    for item in items:
        pattern, _, at = item.partition("@")
        ranges(pattern)
        plan.append((float(at), pattern))
    return plan


def scan_at(plan, now, stamp):
    """The LaserScan stamped `stamp` of the last pattern in `plan` due by `now` seconds
    ("clear" before the first)."""
    current = [p for at, p in plan if at <= now]
    scan = LaserScan()
    scan.header.stamp = stamp
    scan.header.frame_id = "camera_depth_frame"
    scan.angle_min, scan.angle_max = -0.5, 0.5
    scan.angle_increment = 1.0 / (N - 1)
    scan.range_min, scan.range_max = 0.45, 8.0
    scan.ranges = ranges(current[-1] if current else "clear")
    return scan


def split_triggers(items):
    """The timed items, and [(path, pattern)] of those due when a file exists."""
    timed, triggered = [], []
    for item in items:
        pattern, _, at = item.partition("@")
        if at.startswith("/"):
            ranges(pattern)  # an unknown pattern exits here
            triggered.append((at, pattern))
        else:
            timed.append(item)
    return timed, triggered


def main():
    timed, triggered = split_triggers(rospy.myargv()[1:])
    plan = parse_plan(timed)
    rospy.init_node("fake_scan")
    pub = rospy.Publisher("scan", LaserScan, queue_size=10)
    while pub.get_num_connections() == 0 and not rospy.is_shutdown():
        time.sleep(0.02)
    start = time.monotonic()
    while not rospy.is_shutdown():
        for path, pattern in [t for t in triggered if os.path.exists(t[0])]:
            plan.append((-math.inf, pattern))  # due from now on; last, so it wins
            triggered.remove((path, pattern))
        pub.publish(scan_at(plan, time.monotonic() - start, rospy.Time.now()))
        time.sleep(0.1)


if __name__ == "__main__":
    sys.exit(main())
