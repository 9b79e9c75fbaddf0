"""Range handling: NaN and +/-inf per REP 117, the middle beam, the printed line."""

import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from wanderbot.ranges import format_range_ahead, middle_range, min_range  # noqa: E402

NAN, INF = math.nan, math.inf


def test_min_range_skips_nan():
    # The book's min() returns 2.0 here because every comparison with NaN is false.
    assert min_range([NAN, 2.0, 0.5, NAN]) == 0.5
    assert min_range([2.0, NAN, 0.5]) == 0.5


def test_min_range_plus_inf_is_clear_and_minus_inf_is_an_obstacle():
    assert min_range([INF, INF]) == INF
    assert min_range([INF, 3.0]) == 3.0
    assert min_range([3.0, -INF]) == 0.0


def test_min_range_all_nan_or_empty_is_unknown():
    assert min_range([NAN, NAN]) is None
    assert min_range([]) is None


def test_min_range_respects_sensor_limits():
    assert min_range([0.1, 5.0], range_min=0.45, range_max=8.0) == 0.0
    assert min_range([9.0], range_min=0.45, range_max=8.0) == INF


def test_middle_range_picks_the_centre_beam():
    assert middle_range([1.0, 2.0, 3.0]) == 2.0
    assert middle_range([1.0, 2.0, 3.0, 4.0]) == 3.0  # len // 2, as the book indexes
    assert middle_range([1.0, NAN, 3.0]) is None
    assert middle_range([]) is None


def test_format_range_ahead():
    assert format_range_ahead(1.234) == "range ahead: 1.2"
    assert format_range_ahead(0.0) == "range ahead: 0.0"
    assert "inf" in format_range_ahead(INF)
    assert "unknown" in format_range_ahead(None)
