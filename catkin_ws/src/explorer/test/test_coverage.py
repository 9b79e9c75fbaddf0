import math

import numpy as np
import pytest
from explorer.coverage import coverage, known_at, reachable_free


def two_rooms():
    """10 x 20 cells at 0.1 m, origin (-1, -1): two rooms split by a full wall at column 10,
    so only the left one (8 x 9 free cells) is reachable from a start in it."""
    occupied = np.zeros((10, 20), dtype=bool)
    occupied[0, :] = occupied[-1, :] = occupied[:, 0] = occupied[:, -1] = True
    occupied[:, 10] = True
    return occupied, 0.1, (-1.0, -1.0)


def test_reachable_free_stops_at_walls_and_needs_a_free_start():
    occupied, _, _ = two_rooms()
    region = reachable_free(occupied, (5, 3))
    assert region.sum() == 8 * 9 and not region[:, 10:].any()
    assert not reachable_free(occupied, (0, 0)).any()  # on a wall
    assert not reachable_free(occupied, (50, 3)).any()  # outside


def test_a_map_of_the_left_room_covers_all_of_it_wherever_its_grid_lies():
    occupied, res, origin = two_rooms()
    # The map: its own grid (0.05 m), known over the left room only, placed in the world
    # by a translation and a quarter turn.
    values = np.full((40, 40), -1, dtype=np.int8)
    theta = math.pi / 2
    map_origin = (0.05, -1.0, theta)  # cell (0, 0)'s corner in the world
    rows, cols = np.mgrid[0:40, 0:40]
    # World position of each map cell's centre.
    mx, my = (cols + 0.5) * 0.05, (rows + 0.5) * 0.05
    wx = map_origin[0] + math.cos(theta) * mx - math.sin(theta) * my
    wy = map_origin[1] + math.sin(theta) * mx + math.cos(theta) * my
    values[(wx > -1.0) & (wx < 0.05) & (wy > -1.0) & (wy < 0.0)] = 0
    assert coverage(occupied, res, origin, (-0.6, -0.5), values, 0.05, map_origin) == 1.0
    # Half the room unknown (y above -0.5): about half covered.
    values[wy > -0.5] = -1
    share = coverage(occupied, res, origin, (-0.6, -0.7), values, 0.05, map_origin)
    assert share == pytest.approx(4 / 8, abs=0.13)


def test_known_at_is_false_outside_the_map():
    values = np.zeros((2, 2), dtype=np.int8)
    known = known_at(values, 1.0, (0.0, 0.0, 0.0), np.array([0.5, 1.5, 2.5]), np.array([0.5] * 3))
    assert known.tolist() == [True, True, False]
