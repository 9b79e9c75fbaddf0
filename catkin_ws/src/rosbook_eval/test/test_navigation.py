import math

import numpy as np
import pytest
from rosbook_eval.navigation import (
    grid_of_saved_map,
    leg_lengths,
    path_lengths,
    pick_goals,
    score_navigation,
)
from rosbook_eval.poses import Trajectory


def saved_room(size=80, resolution=0.05):
    """A 4 x 4 m room (walls 100) with an unknown strip along its east side: map frame origin
    at the room's centre, as a SLAM map begun there."""
    cells = np.zeros((size, size), dtype=np.int8)
    cells[:, 60:] = -1
    cells[0, :] = cells[-1, :] = cells[:, 0] = cells[:, -1] = 100
    return cells, resolution, (-2.0, -2.0, 0.0)


def test_unknown_cells_are_solid_and_goals_keep_their_clearance():
    grid = grid_of_saved_map(*saved_room())
    goals = pick_goals(grid, 3, goal_clearance=0.5, min_leg=1.0)
    assert len(goals) == 3
    for (x, y, _), length in goals:
        assert -1.5 <= x <= 1.0 - 0.5 + 0.05 and -1.5 <= y <= 1.5, (x, y)  # not the unknown
        assert length >= 1.0
    # Spread out: no two goals (or a goal and the start) closer than a metre.
    points = [(0.0, 0.0)] + [g[:2] for g, _ in goals]
    for a in range(len(points)):
        for b in range(a):
            assert math.dist(points[a], points[b]) > 1.0


def test_seeded_goals_repeat_and_a_start_in_a_wall_is_an_error():
    grid = grid_of_saved_map(*saved_room())
    assert pick_goals(grid, 2, 0.5, 1.0, seed=3) == pick_goals(grid, 2, 0.5, 1.0, seed=3)
    walled = grid_of_saved_map(*saved_room(), start=(-1.99, 0.0, 0.0))
    with pytest.raises(ValueError, match="not in free space"):
        pick_goals(walled, 2, 0.5, 1.0)


def test_path_lengths_go_round_a_wall():
    region = np.ones((10, 10), dtype=bool)
    region[0:9, 5] = False  # a wall with a gap at the top row
    dist = path_lengths(region, 1.0, (0, 0))
    assert dist[0, 9] > 9 + 8  # up, across the gap, down
    region[9, 5] = False  # closed
    assert np.isinf(path_lengths(region, 1.0, (0, 0))[0, 9])


def test_score_navigation_measures_in_the_world():
    # The map frame sits at (10, 0) rotated 90 degrees in the world; the robot drove from
    # the map's origin to (2, 0) on the map, i.e. (10, 2) in the world, and stopped 0.1 m short.
    frame = (10.0, 0.0, math.pi / 2)
    t = np.linspace(0.0, 10.0, 101)
    truth = Trajectory(t, [(10.0, 0.19 * s, math.pi / 2) for s in t])
    estimate = Trajectory(t, [(0.19 * s + 0.05, 0.0, 0.0) for s in t])  # 5 cm ahead
    goals = [
        {"goal": (2.0, 0.0, 0.1), "state": "SUCCEEDED", "sent": 0.0, "ended": 10.0, "path_m": 2.0}
    ]
    figures = score_navigation(truth, estimate, goals, frame, top_speed=0.5)
    assert figures["reached"] == figures["goals"] == 1
    (goal,) = figures["per_goal"]
    assert goal["position_error_m"] == pytest.approx(0.1)
    assert goal["heading_error_rad"] == pytest.approx(0.1)
    assert goal["time_ratio"] == pytest.approx(10.0 / 4.0)
    assert figures["localization_rms_m"] == pytest.approx(0.05)
    assert figures["localization_max_m"] == pytest.approx(0.05)


def test_goal_times_off_the_truths_clock_are_an_error():
    # Wall-clock goal times against a sim-time bag (a client that missed /use_sim_time)
    # would otherwise all be scored at the bag's last pose.
    t = np.linspace(0.0, 10.0, 101)
    truth = Trajectory(t, [(0.1 * s, 0.0, 0.0) for s in t])
    goal = {"goal": (1.0, 0.0, 0.0), "state": "SUCCEEDED", "path_m": 1.0}
    late = dict(goal, sent=1.79e9, ended=1.79e9 + 4.6)
    with pytest.raises(ValueError, match="another clock"):
        score_navigation(truth, truth, [late], (0.0, 0.0, 0.0), top_speed=0.5)
    just_after = dict(goal, sent=2.0, ended=10.5)  # within the slack: the last pose
    figures = score_navigation(truth, truth, [just_after], (0.0, 0.0, 0.0), top_speed=0.5)
    assert figures["per_goal"][0]["position_error_m"] == pytest.approx(0.0)


def test_leg_lengths_from_the_start_through_each_goal():
    grid = grid_of_saved_map(*saved_room())
    lengths = leg_lengths(grid, [(0.5, 0.0, 0.0), (0.5, 1.0, 0.0), (1.5, 0.0, 0.0)])
    assert lengths[0] == pytest.approx(0.5, abs=0.06)
    assert lengths[1] == pytest.approx(1.0, abs=0.06)
    assert math.isinf(lengths[2])  # in the unknown


def test_goals_near_a_route_stay_near_it():
    grid = grid_of_saved_map(*saved_room())
    route = [(x, 0.0) for x in np.linspace(-1.5, 0.5, 41)]  # along y = 0 only
    goals = pick_goals(grid, 2, 0.5, 0.5, near=route, near_radius=0.2)
    assert len(goals) == 2
    for (x, y, _), _ in goals:
        assert abs(y) <= 0.2 + 0.05, (x, y)
