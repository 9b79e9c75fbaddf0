"""The w/x/a/d/s key mapping of chapter 8, with one sign convention for every variant.

REP 103: x forward, z up, so a positive angular z turns left. The book's first three
listings map 'a' to -1 (a right turn); only its ramps listing has it right.
"""

# key: (linear x, angular z) in units of the scales
KEY_MAPPING = {
    "w": (1.0, 0.0),
    "x": (-1.0, 0.0),
    "a": (0.0, 1.0),
    "d": (0.0, -1.0),
    "s": (0.0, 0.0),
}


def velocities_for_key(text, linear_scale=1.0, angular_scale=1.0):
    """(linear x, angular z) for the first character of `text`, or None if unknown/empty."""
    if not text:
        return None
    unit = KEY_MAPPING.get(text[0])
    if unit is None:
        return None
    return (unit[0] * linear_scale, unit[1] * angular_scale)
