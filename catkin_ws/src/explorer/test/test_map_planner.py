"""MapPlanner on an OccupancyGrid-like array: close approaches, set-aside frontiers, a
robot off the traversable grid."""

import math

import numpy as np
from explorer.map_planner import MapPlanner, unknown_neighbours

RES = 0.05


def shadowed_corner():
    """10 m x 10 m (OccupancyGrid values, row 0 at y = 0): a 2 m corridor along the bottom
    and one up the left side, round a solid block (x, y > 2). The left corridor is known
    only below the shadow the block's corner (2, 2) casts for a robot down the bottom
    corridor: the frontier is a diagonal that a view from the bottom corridor grazes."""
    n = int(10 / RES)
    data = np.zeros((n, n), dtype=np.int8)
    ys, xs = (np.mgrid[0:n, 0:n] + 0.5) * RES
    data[(xs > 2.0) & (ys > 2.0)] = 100  # the block
    data[:2, :] = data[-2:, :] = data[:, :2] = data[:, -2:] = 100  # outer walls
    shadow = (xs < 2.0) & (ys > 2.0 + 0.5 * (2.0 - xs))
    data[shadow & (data == 0)] = -1
    return data


def planner_on(data):
    planner = MapPlanner()
    assert planner.set_map(data, RES, 0.0, 0.0)
    return planner


def frontier_points(planner):
    prep = planner.prepared
    rows, cols = np.nonzero(prep.labels)
    return np.column_stack(prep.geometry.to_world(rows, cols))


def test_a_close_approach_stands_at_the_frontier_and_looks_into_the_unknown():
    planner = planner_on(shadowed_corner())
    frontier = frontier_points(planner)
    assert len(frontier) and frontier[:, 0].max() < 2.2  # the diagonal in the left corridor
    far = planner.plan(6.0, 1.0)
    assert far is not None and not far.close
    # The explorer notes where a vain look looked (the plan's target) as a close target.
    near = planner.plan(6.0, 1.0, close_targets=[far.target])
    assert near is not None and near.close

    def gap(goal):
        return np.hypot(*(frontier - goal).T).min()

    # From afar the goal keeps reach_min or more from the frontier; closely, it stands on
    # it (as near as the robot may come to a wall, and a cell).
    params = planner.params
    assert gap(far.goal) >= params.reach_min - RES
    assert gap(near.goal) <= params.robot_radius + params.safety_margin + 2 * RES
    assert tuple(near.path[0]) == (6.0, 1.0)
    # What the looks at the goal would reveal (the true corridor behind the shadow is
    # free): from close by, much more than from afar, where the view grazes the diagonal.
    data = shadowed_corner()
    far_m2 = revealed(data, far.goal, far.look_yaws, params)
    near_m2 = revealed(data, near.goal, near.look_yaws, params)
    assert near_m2 >= 2.0 and near_m2 >= 3 * far_m2


def revealed(data, goal, yaws, params):
    """m^2 of unknown cells a sensor at `goal` sees over the headings `yaws` (rays over
    +-view_half_angle to view_range, stopped by occupied cells; unknown cells are free)."""
    seen = set()
    steps = np.arange(RES / 2, params.view_range, RES / 2)
    for yaw in yaws:
        for bearing in yaw + np.linspace(-params.view_half_angle, params.view_half_angle, 60):
            cols = ((goal[0] + steps * math.cos(bearing)) / RES).astype(int)
            rows = ((goal[1] + steps * math.sin(bearing)) / RES).astype(int)
            for row, col in zip(rows, cols, strict=True):
                if not (0 <= row < data.shape[0] and 0 <= col < data.shape[1]):
                    break
                if data[row, col] == 100:
                    break
                if data[row, col] == -1:
                    seen.add((row, col))
    return len(seen) * RES * RES


def test_set_aside_frontiers_are_not_planned_for():
    planner = planner_on(shadowed_corner())
    frontier = frontier_points(planner)
    # Points along the whole diagonal, blacklist_radius apart at most.
    step = max(1, len(frontier) // 20)
    dead = [tuple(p) for p in frontier[::step]]
    assert planner.plan(6.0, 1.0, dead_frontiers=dead) is None
    assert not planner.start_blocked


def test_a_robot_off_the_traversable_grid_is_reported_blocked():
    planner = planner_on(shadowed_corner())
    assert planner.plan(6.0, 6.0) is None  # inside the block, far from free space
    assert planner.start_blocked
    assert planner.plan(6.0, 1.0) is not None
    assert not planner.start_blocked


def test_unknown_neighbours_of_cells():
    classes = np.zeros((4, 4), dtype=np.uint8)
    classes[0, :] = 1  # UNKNOWN
    found = unknown_neighbours(classes, [[1, 1], [3, 3]])
    assert found.tolist() == [[0, 0], [0, 1], [0, 2]]
    assert unknown_neighbours(classes, np.zeros((0, 2), dtype=int)).shape == (0, 2)


def test_a_frontier_nobody_can_stand_on_is_still_looked_at_from_afar():
    """A 0.4 m gap through a 0.3 m wall, unknown beyond: the frontier at its far end has
    no traversable cell within a close approach, so it is planned for from afar."""
    rows, cols = int(6 / RES), int(10 / RES)
    data = np.zeros((rows, cols), dtype=np.int8)
    ys, xs = (np.mgrid[0:rows, 0:cols] + 0.5) * RES
    data[:2, :] = data[:, :2] = data[:, -2:] = 100
    data[ys > 3.3] = -1  # beyond the wall
    wall = (ys > 3.0) & (ys <= 3.3)
    data[wall & ((xs < 4.8) | (xs > 5.2))] = 100
    planner = planner_on(data)
    far = planner.plan(5.0, 1.5)
    assert far is not None and not far.close
    again = planner.plan(5.0, 1.5, close_targets=[far.target])
    assert again is not None and not again.close
    assert again.goal == far.goal


def pocket(gap):
    """10 m x 6 m: the robot's room (x < 5, known all round) and, through a `gap` m
    opening in a 0.3 m wall at x = 5, a room unknown beyond x = 8.5 (out of reach_max
    from the robot's room)."""
    rows, cols = int(6 / RES), int(10 / RES)
    data = np.zeros((rows, cols), dtype=np.int8)
    ys, xs = (np.mgrid[0:rows, 0:cols] + 0.5) * RES
    data[:2, :] = data[-2:, :] = data[:, :2] = data[:, -2:] = 100
    wall = (xs > 5.0) & (xs <= 5.3)
    data[wall & (np.abs(ys - 3.0) > gap / 2)] = 100
    data[xs > 8.5] = -1
    return data


def test_a_robot_in_a_pocket_only_the_safety_margin_closes_still_gets_out():
    """The robot came in through a gap it fits (0.40 m for its 0.36 m body) which the
    safety margin and the coarse grid's grown obstacles close: it plans through it rather
    than finding no frontier. A closed wall still means none."""
    planner = planner_on(pocket(0.40))
    assert not planner.prepared.costmap.traversable[:, int(5.15 / 0.1)].any()
    plan = planner.plan(2.0, 3.0)
    assert plan is not None and plan.goal[0] > 5.3
    assert np.all(np.abs(plan.path[plan.path[:, 0] > 5.0, 1] - 3.0) < 0.2)  # through the gap
    assert planner.plan(2.0, 3.0, excluded_points=[plan.goal]) is not None
    closed = planner_on(pocket(0.0))
    assert closed.plan(2.0, 3.0) is None and not closed.start_blocked
    # A gap the body does not fit stays closed too.
    assert planner_on(pocket(0.25)).plan(2.0, 3.0) is None
