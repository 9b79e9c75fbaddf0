import math

import numpy as np
import pytest
from rosbook_eval.grids import distance_to_walls, near_wall_share, occupied_points, sample


def wall_grid(resolution=0.1, yaw=0.0):
    cells = np.zeros((20, 20), dtype=np.int8)
    cells[:, 10] = 100  # a wall covering x in [1.0, 1.1), centres at x = 1.05
    return cells, resolution, (0.0, 0.0, yaw)


def test_share_counts_points_within_tolerance_plus_half_a_cell_of_a_wall_centre():
    truth = wall_grid()
    # 0 m, 0.15 m (= 0.10 + half a cell: in), 0.16 m (out), far, off the grid.
    points = np.array([[1.05, 1.05], [1.20, 1.05], [1.21, 1.05], [0.5, 0.5], [9.0, 9.0]])
    assert distance_to_walls(points[:2], truth, 0.2) == pytest.approx([0.0, 0.15])
    assert near_wall_share(points, truth, 0.10) == pytest.approx(2 / 5)
    assert math.isnan(near_wall_share(np.zeros((0, 2)), truth, 0.10))


def test_a_perfect_map_scores_every_wall_and_points_off_centre_are_judged_as_points():
    truth = wall_grid()
    assert near_wall_share(occupied_points(truth), truth, 0.10) == 1.0
    # Centres of a turned SLAM grid fall anywhere in a truth cell: 8 cm beside the wall line
    # is within 0.10 m whatever the point's height.
    ys = np.linspace(0.0, 1.99, 50)
    points = np.column_stack((np.full_like(ys, 1.05 + 0.08), ys))
    assert near_wall_share(points, truth, 0.10) == 1.0


def test_a_map_shifted_by_more_than_the_tolerance_misses():
    cells, resolution, origin = wall_grid()
    shifted = (cells, resolution, (0.2, 0.0, 0.0))
    assert near_wall_share(occupied_points(shifted), wall_grid(), 0.10) == 0.0


def test_sample_reads_cells_and_marks_points_off_the_grid():
    cells, resolution, origin = wall_grid()
    assert list(sample((cells, resolution, origin), [1.05, 0.5, -1.0], [1.0, 1.0, 1.0])) == [
        100,
        0,
        -2,
    ]
