"""Reading LaserScan ranges that may hold NaN and +/-inf (REP 117).

REP 117: NaN is an invalid reading, -inf means an object closer than range_min, +inf means
nothing within range_max. Python's min() over a list holding NaN returns garbage (the
comparison with NaN is always false), which is the bug in the book's wander.py.
"""

import math


def usable_range(value, range_min=0.0, range_max=math.inf):
    """Map one reading to a distance, or None when it says nothing (NaN)."""
    if value is None or math.isnan(value):
        return None
    if value == -math.inf:
        return 0.0  # too close to measure: an obstacle right here
    if value == math.inf:
        return math.inf  # nothing within range_max: clear
    if value < range_min:
        return 0.0
    if value > range_max:
        return math.inf
    return float(value)


def min_range(ranges, range_min=0.0, range_max=math.inf):
    """Closest obstacle over all beams; inf when all clear, None when every reading is NaN."""
    values = [usable_range(r, range_min, range_max) for r in ranges]
    values = [v for v in values if v is not None]
    return min(values) if values else None


def middle_range(ranges, range_min=0.0, range_max=math.inf):
    """The beam straight ahead (the middle of an odd or even scan, as the book picks it)."""
    if len(ranges) == 0:
        return None
    return usable_range(ranges[len(ranges) // 2], range_min, range_max)


def format_range_ahead(value):
    """The book's `range ahead: %0.1f` line, with words for the special readings."""
    if value is None:
        return "range ahead: unknown (no valid reading)"
    if value == math.inf:
        return "range ahead: inf (nothing in range)"
    return "range ahead: %0.1f" % value
