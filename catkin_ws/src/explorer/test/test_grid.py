import numpy as np
import pytest
from explorer.grid import FREE, OCCUPIED, UNKNOWN, GridGeometry, classify, downsample, known_window


def test_classify_maps_values_to_classes_with_thresholds():
    values = np.array([-1, 0, 25, 26, 64, 65, 100, 101, -5])
    expected = [UNKNOWN, FREE, FREE, UNKNOWN, UNKNOWN, OCCUPIED, OCCUPIED, UNKNOWN, UNKNOWN]
    assert classify(values).tolist() == expected


def test_geometry_cell_and_world_round_trip():
    g = GridGeometry(0.1, -2.0, 1.0, 40, 30)
    row, col = g.to_cell(-1.95, 1.05)
    assert (row, col) == (0, 0)
    x, y = g.to_world(5, 7)
    assert (x, y) == pytest.approx((-2.0 + 0.75, 1.0 + 0.55))
    assert g.to_cell(x, y) == (5, 7)
    assert not g.contains(30, 0) and g.contains(29, 39)


def test_sub_geometry_keeps_the_window_origin():
    g = GridGeometry(0.05, 0.0, 0.0, 100, 100).sub(10, 20, 5, 5, factor=2)
    assert (g.resolution, g.origin_x, g.origin_y) == pytest.approx((0.1, 1.0, 0.5))


def test_known_window_bounds_known_cells_plus_margin():
    classes = np.full((20, 30), UNKNOWN, dtype=np.uint8)
    classes[5:8, 10:12] = FREE
    assert known_window(classes, 2) == (3, 8, 10, 14)
    assert known_window(np.full((4, 4), UNKNOWN, dtype=np.uint8), 2) is None


def test_downsample_occupied_wins_then_free_majority():
    classes = np.array(
        [
            [FREE, FREE, FREE, UNKNOWN],
            [FREE, OCCUPIED, UNKNOWN, UNKNOWN],
            [FREE, UNKNOWN, UNKNOWN, UNKNOWN],
            [UNKNOWN, FREE, UNKNOWN, UNKNOWN],
        ],
        dtype=np.uint8,
    )
    out = downsample(classes, 2)
    assert out.tolist() == [[OCCUPIED, UNKNOWN], [FREE, UNKNOWN]]


def test_downsample_pads_ragged_edges_with_unknown():
    classes = np.full((3, 5), FREE, dtype=np.uint8)
    out = downsample(classes, 2)
    assert out.shape == (2, 3)
    assert out[0, 0] == FREE and out[1, 2] == UNKNOWN  # one free cell of four
