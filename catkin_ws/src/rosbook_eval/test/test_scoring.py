import math

import numpy as np
import pytest
from rosbook_eval.poses import Trajectory, chain
from rosbook_eval.scoring import figures_json, place_grid, score, score_slam_figures


def room(size=40, resolution=0.1):
    cells = np.zeros((size, size), dtype=np.int8)
    cells[0, :] = cells[-1, :] = cells[:, 0] = cells[:, -1] = 100
    return cells, resolution, (-2.0, -2.0, 0.0)


def test_place_grid_moves_the_origin_into_the_parent_frame():
    cells, res, _ = room()
    placed = place_grid((cells, res, (1.0, 0.0, 0.0)), (0.0, 0.0, math.pi / 2))
    assert placed[2] == pytest.approx((0.0, 1.0, math.pi / 2))


def test_perfect_slam_scores_zero_error_and_every_wall():
    grid = room()
    stamps = np.arange(0, 10, 1.0)
    truth = Trajectory(stamps, [(0.1 * t, 0.0, 0.0) for t in stamps])
    drift = Trajectory(stamps, [(0.1 * t, 0.02 * t, 0.0) for t in stamps])
    correction = Trajectory(stamps, [(0.0, -0.02 * t, 0.0) for t in stamps])
    figures = score(truth, drift, chain(correction, drift), grid, grid)
    for placement in ("fit", "start"):
        assert figures[placement]["slam_rms"] == pytest.approx(0.0, abs=1e-9)
        assert figures[placement]["walls"] == 1.0
    assert figures["start"]["odom_final"] == pytest.approx(0.18)
    # The best fit turns the drifting odometry onto the truth's line, but it still bends away.
    assert 0.0 < figures["fit"]["odom_rms"] < figures["start"]["odom_rms"]
    assert set(figures["tracks"]) == {"odometry", "SLAM"}
    assert figures["poses"] == 10 and figures["occupied_cells"] == 4 * 39


def test_a_turned_but_consistent_map_scores_zero_after_the_best_fit():
    grid = room()
    stamps = np.arange(0, 10, 1.0)
    truth = Trajectory(stamps, [(0.1 * t, 0.05 * t, 0.0) for t in stamps])
    odom = Trajectory(stamps, [(0.1 * t, 0.05 * t, 0.0) for t in stamps])
    # SLAM turned its heading by 0.05 rad just after the start (map->odom is the identity at
    # the first scan): from then on the whole path and map are turned about the start.
    correction = Trajectory(stamps, [(0.0, 0.0, 0.05 if t > 0 else 0.0) for t in stamps])
    figures = score(truth, odom, chain(correction, odom), grid, grid)
    assert figures["fit"]["slam_rms"] == pytest.approx(0.0, abs=1e-9)
    assert figures["start"]["slam_final"] == pytest.approx(0.05 * math.hypot(0.9, 0.45), rel=1e-3)


def test_slam_poses_outside_the_truth_span_are_not_scored():
    grid = room()
    truth = Trajectory([2.0, 8.0], [(0.0, 0.0, 0.0), (0.6, 0.0, 0.0)])
    stamps = np.arange(0, 11, 1.0)
    slam = Trajectory(stamps, [(0.1 * (t - 2), 0.0, 0.0) for t in stamps])
    figures = score(truth, slam, slam, grid, grid)
    assert figures["poses"] == 7
    assert figures["fit"]["slam_max"] == pytest.approx(0.0, abs=1e-9)
    with pytest.raises(ValueError, match="fewer than two SLAM poses"):
        score(Trajectory([20.0, 30.0], [(0, 0, 0), (1, 0, 0)]), slam, slam, grid, grid)


def test_both_entry_points_keys_carry_the_same_numbers():
    grid = room()
    stamps = np.arange(0, 10, 1.0)
    truth = Trajectory(stamps, [(0.1 * t, 0.05 * t, 0.0) for t in stamps])
    odom = Trajectory(stamps, [(0.1 * t, 0.07 * t, 0.01 * t) for t in stamps])
    figures = score(truth, odom, odom, grid, grid)
    cli = score_slam_figures(figures, "fit")
    demo = figures_json(figures)
    for cli_key, demo_key in (
        ("slam_rms", "slam_rms_m"),
        ("odom_rms", "odom_rms_m"),
        ("near_wall_fraction", "walls_within_tolerance"),
    ):
        assert cli[cli_key] == demo[demo_key]
        assert cli[cli_key + "_start"] == demo[demo_key + "_start"]
    start_first = score_slam_figures(figures, "start")
    assert start_first["slam_rms"] == cli["slam_rms_start"]
    assert start_first["slam_rms_fit"] == cli["slam_rms"]
