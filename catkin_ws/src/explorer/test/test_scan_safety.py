import math

import numpy as np
import pytest
from explorer.scan_safety import clearance_ahead, scan_clearance
from sensor_msgs.msg import LaserScan

FOV = math.radians(58)


def scan(values, count=641):
    ranges = np.full(count, math.inf)
    for index, value in values.items():
        ranges[index] = value
    return ranges, -FOV / 2, FOV / (count - 1)


def clear(ranges, angle_min, increment, half_width=0.22, offset=0.0):
    return clearance_ahead(ranges, angle_min, increment, 0.45, 8.0, half_width, offset)


def test_nothing_seen_is_infinite_clearance():
    assert clear(*scan({})) == math.inf


def test_an_obstacle_straight_ahead_measured_from_the_robot_centre():
    assert clear(*scan({320: 2.0}), offset=-0.087) == pytest.approx(2.0 - 0.087)


def test_obstacles_outside_the_robot_corridor_are_ignored():
    # 20 degrees off at 2 m: 0.68 m to the side
    ranges, a0, inc = scan({320 + int(round(math.radians(20) / (FOV / 640))): 2.0})
    assert clear(ranges, a0, inc) == math.inf


def test_nan_is_no_reading_and_minus_inf_blocks():
    assert clear(*scan({320: math.nan})) == math.inf
    assert clear(*scan({320: -math.inf})) == 0.0


def test_out_of_range_finite_readings_are_ignored():
    assert clear(*scan({320: 0.2, 321: 9.5})) == math.inf


def test_empty_scan():
    assert clearance_ahead([], 0.0, 0.01, 0.45, 8.0, 0.22) == math.inf


def test_a_wide_scanner_ignores_what_is_behind():
    """A 360-degree scan: a -inf or finite return straight behind does not block."""
    count = 720
    ranges = np.full(count, math.inf)
    ranges[0] = -math.inf  # angle -pi: straight behind
    ranges[1] = 0.6
    increment = 2 * math.pi / count
    assert clearance_ahead(ranges, -math.pi, increment, 0.45, 30.0, 0.22) == math.inf
    ranges[count // 2] = -math.inf  # straight ahead
    assert clearance_ahead(ranges, -math.pi, increment, 0.45, 30.0, 0.22) == 0.0


def test_a_laser_scan_message_gives_the_same_clearance():
    ranges, angle_min, increment = scan({320: 2.0, 100: 1.0})
    msg = LaserScan(angle_min=angle_min, angle_increment=increment, range_min=0.45)
    msg.range_max, msg.ranges = 8.0, list(ranges)
    expected = clear(ranges, angle_min, increment, offset=-0.087)
    assert scan_clearance(msg, 0.22, -0.087) == expected == pytest.approx(2.0 - 0.087)
