import numpy as np
from explorer.grid import GridGeometry
from move_base_lite.global_planner import GlobalPlanner


def corridor_map():
    """4 m x 2 m at 0.05 m: walls round it and a wall across x = 2 m with a gap at the top."""
    values = np.zeros((40, 80), dtype=np.int8)
    values[0, :] = values[-1, :] = values[:, 0] = values[:, -1] = 100
    values[:28, 40] = 100
    return values, GridGeometry(0.05, 0.0, 0.0, 80, 40)


def test_the_path_goes_round_the_wall_and_keeps_the_robot_radius():
    planner = GlobalPlanner(*corridor_map())
    result = planner.plan((1.0, 0.5), (3.0, 0.5))
    assert result.path is not None, result.reason
    assert np.allclose(result.path[-1], (3.0, 0.5))
    assert result.path[:, 1].max() > 1.4  # through the gap near the top
    rows, cols = planner.geometry.to_cell(result.path[:, 0], result.path[:, 1])
    assert (planner.costmap.clearance[rows, cols] > 0.18).all()


def test_goals_in_walls_or_off_the_map_are_refused_with_a_reason():
    planner = GlobalPlanner(*corridor_map())
    in_wall = planner.plan((1.0, 0.5), (2.02, 0.5))
    assert in_wall.path is None and in_wall.goal_invalid
    assert "obstacle" in in_wall.reason
    off_map = planner.plan((1.0, 0.5), (9.0, 0.5))
    assert off_map.goal_invalid and "outside the map" in off_map.reason
    far = planner.plan((1.0, 0.5), (1e300, 0.5))  # said in a few digits, not in 300
    assert far.goal_invalid and "goal (1e+300, 0.50) is outside the map" in far.reason


def test_obstacles_the_scan_adds_block_the_gap():
    values, geometry = corridor_map()
    planner = GlobalPlanner(values, geometry)
    marked = np.zeros(values.shape, dtype=bool)
    marked[28:, 40] = True  # something closes the gap
    planner.update_obstacles(marked)
    result = planner.plan((1.0, 0.5), (3.0, 0.5))
    assert result.path is None and not result.goal_invalid
    assert "no path" in result.reason


def test_a_goal_covered_only_by_scan_obstacles_is_worth_a_retry():
    values, geometry = corridor_map()
    planner = GlobalPlanner(values, geometry)
    marked = np.zeros(values.shape, dtype=bool)
    marked[10, 60] = True  # (3.0, 0.5)
    planner.update_obstacles(marked)
    result = planner.plan((1.0, 0.5), (3.0, 0.5))
    assert result.path is None and not result.goal_invalid
    assert "the scan sees" in result.reason
