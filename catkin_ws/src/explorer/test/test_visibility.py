import math

import numpy as np
import pytest
from explorer.grid import FREE, OCCUPIED, UNKNOWN
from explorer.visibility import line_of_sight, sweep_headings


def test_line_of_sight_is_blocked_by_walls_and_unknown():
    classes = np.full((10, 10), FREE, dtype=np.uint8)
    classes[2:8, 5] = OCCUPIED
    classes[9, 5] = UNKNOWN
    targets = [(5, 8), (0, 6), (5, 3)]
    assert line_of_sight(classes, (5, 1), targets).tolist() == [False, True, True]
    assert line_of_sight(classes, (9, 1), [(9, 9), (7, 9)]).tolist() == [False, True]
    assert line_of_sight(classes, (5, 1), []).size == 0


def test_sweep_of_a_narrow_spread_is_one_heading():
    assert sweep_headings([0.1, 0.2, 0.3], 0.45, 0.9) == [pytest.approx(0.2)]


def test_sweep_covers_a_wide_spread_in_steps_across_pi():
    bearings = [math.pi - 0.5, -math.pi + 0.5, math.pi]  # 1 rad wide, around +-pi
    headings = sweep_headings(bearings, 0.3, 0.6)
    assert len(headings) == 2
    for b in bearings:
        assert min(abs(math.remainder(b - h, 2 * math.pi)) for h in headings) <= 0.3 + 1e-9
    steps = [
        abs(math.remainder(b - a, 2 * math.pi))
        for a, b in zip(headings, headings[1:], strict=False)
    ]
    assert all(s <= 0.6 + 1e-9 for s in steps)


def test_sweep_of_nothing_is_empty():
    assert sweep_headings([], 0.45, 0.9) == []
