import numpy as np
import pytest
from explorer.costmap import inflate
from explorer.grid import FREE, OCCUPIED, UNKNOWN


def room(size=40):
    classes = np.full((size, size), FREE, dtype=np.uint8)
    classes[0, :] = classes[-1, :] = classes[:, 0] = classes[:, -1] = OCCUPIED
    return classes


def test_cells_within_the_robot_radius_of_a_wall_are_not_traversable():
    costmap = inflate(room(), 0.1, robot_radius=0.18, inflation_radius=0.30)
    # wall at column 0; cell centres at 0.1 m steps; clearance = centre distance - half cell
    row = costmap.traversable[20]
    assert not row[1] and not row[2]  # 0.05 m and 0.15 m from the wall's edge
    assert row[3]  # 0.25 m
    assert costmap.clearance[20, 3] == pytest.approx(0.25)


def test_cost_falls_to_zero_at_the_inflation_radius():
    costmap = inflate(room(), 0.1, robot_radius=0.18, inflation_radius=0.5, cost_scale=2.0)
    cost = costmap.cost[20]
    assert cost[3] > cost[4] > cost[5] > 0  # 0.25, 0.35, 0.45 m
    assert cost[6] == 0 and cost[20] == 0


def test_unknown_cells_are_not_traversable_and_do_not_inflate():
    classes = room()
    classes[10:20, 10:20] = UNKNOWN
    costmap = inflate(classes, 0.1, 0.18, 0.3)
    assert not costmap.traversable[15, 15]
    assert costmap.traversable[15, 9]  # next to unknown, far from walls


def test_no_obstacles_means_infinite_clearance():
    costmap = inflate(np.full((5, 5), FREE, dtype=np.uint8), 0.1, 0.18, 0.3)
    assert costmap.traversable.all() and np.isinf(costmap.clearance).all()


def test_inflation_smaller_than_the_robot_is_refused():
    with pytest.raises(ValueError):
        inflate(room(), 0.1, robot_radius=0.3, inflation_radius=0.2)
