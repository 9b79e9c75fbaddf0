import math

import numpy as np
import pytest
from rosbook_demo.scoring import score, wall_hits, world_from_map
from rosbook_demo.trajectory import Trajectory


def room(size=40, resolution=0.1):
    cells = np.zeros((size, size), dtype=np.int8)
    cells[0, :] = cells[-1, :] = cells[:, 0] = cells[:, -1] = 100
    return cells, resolution, (-2.0, -2.0, 0.0)


def test_wall_hits_counts_points_near_true_walls():
    cells, res, origin = room()
    near = np.array([[-1.95, 0.0], [-1.90, 0.5]])  # on and 5 cm from the west wall
    far = np.array([[0.0, 0.0]])
    assert wall_hits(near, (cells, res, origin), 0.10) == 1.0
    assert wall_hits(np.vstack((near, far)), (cells, res, origin), 0.10) == pytest.approx(2 / 3)
    assert math.isnan(wall_hits(np.zeros((0, 2)), (cells, res, origin), 0.10))


def test_points_outside_the_truth_map_miss():
    cells, res, origin = room()
    assert wall_hits(np.array([[50.0, 50.0]]), (cells, res, origin), 0.10) == 0.0


def test_map_frame_is_where_odometry_started_in_the_world():
    truth = Trajectory([0.0], [(3.0, 1.0, math.pi / 2)])
    odom = Trajectory([0.0], [(0.0, 0.0, 0.0)])
    identity = Trajectory([0.0], [(0.0, 0.0, 0.0)])
    assert world_from_map(truth, odom, identity) == pytest.approx((3.0, 1.0, math.pi / 2))


def test_perfect_slam_scores_zero_error_and_every_wall():
    cells, res, origin = room()
    stamps = np.arange(0, 10, 1.0)
    truth = Trajectory(stamps, [(0.1 * t, 0.0, 0.0) for t in stamps])
    drift = Trajectory(stamps, [(0.1 * t, 0.02 * t, 0.0) for t in stamps])
    correction = Trajectory(stamps, [(0.0, -0.02 * t, 0.0) for t in stamps])
    figures, tracks, _ = score(truth, drift, correction, (cells, res, origin), (cells, res, origin))
    assert figures["slam_rms_m"] == pytest.approx(0.0, abs=1e-9)
    assert figures["slam_rms_m_start"] == pytest.approx(0.0, abs=1e-9)
    assert figures["odom_final_m_start"] == pytest.approx(0.18)
    # The best fit turns the drifting odometry onto the truth's line, but it still bends away.
    assert 0.0 < figures["odom_rms_m"] < figures["odom_rms_m_start"]
    assert figures["walls_within_tolerance"] == 1.0
    assert set(tracks) == {"odometry", "SLAM"}


def test_a_turned_but_consistent_map_scores_zero_after_the_best_fit():
    cells, res, origin = room()
    stamps = np.arange(0, 10, 1.0)
    truth = Trajectory(stamps, [(0.1 * t, 0.05 * t, 0.0) for t in stamps])
    odom = Trajectory(stamps, [(0.1 * t, 0.05 * t, 0.0) for t in stamps])
    # SLAM turned its heading by 0.05 rad just after the start (map->odom is the identity at
    # the first scan): from then on the whole path and map are turned about the start.
    turn = (0.0, 0.0, 0.05)
    correction = Trajectory(stamps, [turn if t > 0 else (0.0, 0.0, 0.0) for t in stamps])
    figures, _, _ = score(truth, odom, correction, (cells, res, origin), (cells, res, origin))
    assert figures["slam_rms_m"] == pytest.approx(0.0, abs=1e-9)
    assert figures["slam_final_m_start"] == pytest.approx(0.05 * math.hypot(0.9, 0.45), rel=1e-3)
