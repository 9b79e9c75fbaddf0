"""Free distance ahead from a LaserScan's ranges, with REP 117's special values:
NaN = no valid reading (ignored), +inf = nothing within range_max (free),
-inf = something closer than range_min (blocked)."""

import math

import numpy as np


def clearance_ahead(
    ranges, angle_min, angle_increment, range_min, range_max, half_width, sensor_offset=0.0
):
    """Distance (m) along the robot's heading to the nearest return inside a corridor of
    `half_width` either side of the robot's centre line; inf when none.

    `sensor_offset` is the sensor's x in the robot frame (negative: behind the centre);
    the result is measured from the robot's centre. -inf readings inside the corridor
    give 0 (too close to measure: blocked)."""
    r = np.asarray(ranges, dtype=float)
    if r.size == 0:
        return math.inf
    angles = angle_min + angle_increment * np.arange(r.size)
    too_close = np.isneginf(r)
    valid = np.isfinite(r) & (r >= range_min) & (r <= range_max)
    if too_close.any():
        # Without a range, take the beam's nearest measurable point as the hit (ahead of
        # the robot's centre only: a wide scanner also looks sideways and back).
        lateral = np.abs(range_min * np.sin(angles[too_close]))
        ahead = range_min * np.cos(angles[too_close]) + sensor_offset > 0
        if ((lateral <= half_width) & ahead).any():
            return 0.0
    if not valid.any():
        return math.inf
    x = r[valid] * np.cos(angles[valid]) + sensor_offset
    y = r[valid] * np.sin(angles[valid])
    inside = (np.abs(y) <= half_width) & (x > 0)
    if not inside.any():
        return math.inf
    return float(x[inside].min())


def scan_clearance(scan, half_width, sensor_offset=0.0):
    """clearance_ahead of a sensor_msgs/LaserScan's own angles and limits."""
    return clearance_ahead(
        scan.ranges,
        scan.angle_min,
        scan.angle_increment,
        scan.range_min,
        scan.range_max,
        half_width,
        sensor_offset,
    )
