import math

import numpy as np
import pytest
from explorer.costmap import inflate
from explorer.frontiers import find_frontiers, information_gain
from explorer.grid import FREE, OCCUPIED, UNKNOWN
from explorer.planner import choose_goal, distance_field, extract_path

RES = 0.1


def two_rooms():
    """20 x 40 cells: two rooms joined by a door in a wall at column 20; the right room's
    far end is unknown."""
    classes = np.full((20, 40), FREE, dtype=np.uint8)
    classes[0, :] = classes[-1, :] = classes[:, 0] = classes[:, -1] = OCCUPIED
    classes[:, 20] = OCCUPIED
    classes[8:13, 20] = FREE  # a 0.5 m door
    classes[1:-1, 32:39] = UNKNOWN
    return classes


def test_dijkstra_goes_through_the_door_and_keeps_clear_of_walls():
    classes = two_rooms()
    costmap = inflate(classes, RES, 0.18, 0.3)
    field = distance_field(costmap, (10, 5), RES)
    path = extract_path(field, (10, 28))
    assert path is not None
    assert tuple(path[0]) == (10, 5) and tuple(path[-1]) == (10, 28)
    assert costmap.traversable[path[:, 0], path[:, 1]].all()
    at_wall = path[path[:, 1] == 20]
    assert set(at_wall[:, 0]) <= {10}  # through the middle of the door
    assert field.distance[10, 28] == pytest.approx(2.3, abs=0.2)


def test_unreachable_goal_has_no_path():
    classes = two_rooms()
    classes[8:13, 20] = OCCUPIED  # close the door
    field = distance_field(inflate(classes, RES, 0.18, 0.3), (10, 5), RES)
    assert np.isinf(field.distance[10, 28])
    assert extract_path(field, (10, 28)) is None


def test_start_in_an_inflated_cell_snaps_to_the_nearest_free_one():
    costmap = inflate(two_rooms(), RES, 0.18, 0.3)
    field = distance_field(costmap, (1, 5), RES)  # next to the top wall
    assert field is not None and field.start == (3, 5)


def frontier_setup(classes, start=(10, 5)):
    costmap = inflate(classes, RES, 0.18, 0.3)
    field = distance_field(costmap, start, RES)
    labels, frontiers = find_frontiers(classes, 3)
    information_gain(classes, labels, frontiers, 10)
    return field, labels, frontiers


def test_goal_sees_the_frontier_in_a_straight_line_through_free_space():
    classes = two_rooms()
    field, labels, frontiers = frontier_setup(classes)
    # From the start, the frontier (column 31) is 2.6 m away straight through the door.
    far = choose_goal(field, classes, labels, frontiers, RES, reach=(0.6, 2.6))
    assert far.cell == (10, 5) and far.cost == 0.0
    goal = choose_goal(field, classes, labels, frontiers, RES, reach=(0.6, 1.0))
    r, c = goal.cell
    assert c > 20  # within 1 m of the frontier: in the right room
    assert np.isfinite(field.distance[r, c])
    distances = np.hypot(*(goal.seen - goal.cell).T) * RES
    assert ((distances >= 0.6) & (distances <= 1.0)).all()
    assert (labels[goal.seen[:, 0], goal.seen[:, 1]] == goal.label).all()


def test_more_information_beats_a_slightly_shorter_path():
    classes = np.full((30, 60), FREE, dtype=np.uint8)
    classes[0, :] = classes[-1, :] = classes[:, 0] = classes[:, -1] = OCCUPIED
    classes[1:4, 25:28] = UNKNOWN  # a small pocket near the start
    classes[1:-1, 50:59] = UNKNOWN  # a large unknown area further away
    field, labels, frontiers = frontier_setup(classes, start=(15, 20))
    big = max(frontiers, key=lambda f: f.gain)
    goal = choose_goal(field, classes, labels, frontiers, RES, info_weight=1.0, info_cap=20)
    assert goal.label == big.label
    greedy = choose_goal(field, classes, labels, frontiers, RES, info_weight=0.0)
    assert greedy.label != big.label


def test_excluded_cells_are_never_goals_and_none_when_all_are():
    classes = two_rooms()
    field, labels, frontiers = frontier_setup(classes)
    first = choose_goal(field, classes, labels, frontiers, RES)
    excluded = np.zeros(classes.shape, dtype=bool)
    excluded[first.cell] = True
    second = choose_goal(field, classes, labels, frontiers, RES, excluded=excluded)
    assert second.cell != first.cell
    everything = np.ones(classes.shape, dtype=bool)
    assert choose_goal(field, classes, labels, frontiers, RES, excluded=everything) is None


def test_no_frontiers_no_goal():
    classes = two_rooms()
    classes[classes == UNKNOWN] = FREE
    field, labels, frontiers = frontier_setup(classes)
    assert frontiers == []
    assert choose_goal(field, classes, labels, frontiers, RES) is None


def test_path_length_matches_geometry_in_open_space():
    classes = np.full((30, 30), FREE, dtype=np.uint8)
    field = distance_field(inflate(classes, RES, 0.18, 0.3), (0, 0), RES)
    assert field.distance[0, 20] == pytest.approx(2.0)
    assert field.distance[20, 20] == pytest.approx(2.0 * math.sqrt(2))
