import math

import numpy as np
import pytest
from explorer.follower import FollowerParams, PurePursuit, turn_towards, wrap


def drive(follower, pose, steps=400, dt=0.1):
    x, y, yaw = pose
    for _ in range(steps):
        v, w, arrived = follower.command(x, y, yaw)
        if arrived:
            return (x, y, yaw), True
        x += v * math.cos(yaw) * dt
        y += v * math.sin(yaw) * dt
        yaw = wrap(yaw + w * dt)
    return (x, y, yaw), False


def test_straight_path_full_speed_and_arrival():
    path = np.column_stack([np.linspace(0, 3, 31), np.zeros(31)])
    follower = PurePursuit(path)
    v, w, arrived = follower.command(0.0, 0.0, 0.0)
    assert v == pytest.approx(0.35) and w == pytest.approx(0.0) and not arrived
    (x, y, _), arrived = drive(follower, (0, 0, 0))
    assert arrived and math.hypot(x - 3, y) <= 0.25


def test_large_heading_error_turns_in_place_towards_the_path():
    path = np.column_stack([np.linspace(0, 3, 31), np.zeros(31)])
    v, w, _ = PurePursuit(path).command(0.0, 0.0, math.pi / 2)  # facing left of the path
    assert v == 0.0 and w < 0  # turn right
    v, w, _ = PurePursuit(path).command(0.0, 0.0, -math.pi / 2)
    assert v == 0.0 and w > 0


def test_follows_a_corner_and_respects_limits():
    params = FollowerParams(max_linear=0.3, max_angular=0.8)
    path = np.vstack(
        [
            np.column_stack([np.linspace(0, 2, 21), np.zeros(21)]),
            np.column_stack([np.full(20, 2.0), np.linspace(0.1, 2, 20)]),
        ]
    )
    follower = PurePursuit(path, params)
    x, y, yaw = 0.0, 0.0, 0.0
    worst = 0.0
    for _ in range(600):
        v, w, arrived = follower.command(x, y, yaw)
        if arrived:
            break
        assert 0 <= v <= 0.3 + 1e-9 and abs(w) <= 0.8 + 1e-9
        x, y = x + v * math.cos(yaw) * 0.1, y + v * math.sin(yaw) * 0.1
        yaw = wrap(yaw + w * 0.1)
        worst = max(worst, np.hypot(path[:, 0] - x, path[:, 1] - y).min())
    assert arrived
    assert worst < 0.3  # stays near the path round the corner


def test_clearance_limits_forward_speed():
    path = np.column_stack([np.linspace(0, 3, 31), np.zeros(31)])
    v, _, _ = PurePursuit(path).command(0.0, 0.0, 0.0, clearance=0.1)
    assert v == pytest.approx(0.1)
    v, w, _ = PurePursuit(path).command(0.0, 0.0, 0.0, clearance=0.0)
    assert v == 0.0 and w == 0.0


def test_turn_towards_takes_the_short_way_and_stops():
    w, done = turn_towards(3.0, -3.0)  # 0.28 rad to the left, across +-pi
    assert w > 0 and not done
    assert turn_towards(1.0, 1.05) == (0.0, True)


def test_a_sweep_passes_its_inner_headings_at_full_rate():
    params = FollowerParams()
    slowing, _ = turn_towards(0.0, 0.2, params)
    passing, done = turn_towards(0.0, 0.2, params, passing=True)
    assert not done and passing == pytest.approx(params.max_angular) and slowing < passing
    assert turn_towards(0.0, -0.2, params, passing=True)[0] == pytest.approx(-params.max_angular)
    assert turn_towards(0.0, 0.05, params, passing=True) == (0.0, True)


def test_speed_is_bounded_by_the_turning_rate_not_by_the_heading_error():
    """A moderate heading error on a gentle arc keeps full speed; a sharp arc is slowed to
    max_angular over its curvature (heading_slowdown 0, the default)."""
    path = np.column_stack([np.linspace(0, 3, 31), np.full(31, 0.2)])
    params = FollowerParams()
    v, w, _ = PurePursuit(path, params).command(0.0, 0.0, 0.0)
    assert v == pytest.approx(params.max_linear) and 0 < w <= params.max_angular
    v, w, _ = PurePursuit(path, FollowerParams(heading_slowdown=0.5)).command(0.0, 0.0, 0.0)
    assert v < params.max_linear  # the old rule gives up speed for the same error
    sharp = np.column_stack([np.full(31, 0.1), np.linspace(0, 3, 31)])
    v, w, _ = PurePursuit(sharp, params).command(0.0, 0.0, 0.3)
    assert w == pytest.approx(params.max_angular) and v < params.max_linear


def test_empty_path_is_refused():
    with pytest.raises(ValueError):
        PurePursuit([])
