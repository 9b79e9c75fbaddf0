"""Checks for numeric node parameters, shared by the project's Python nodes (ROS-free: the
caller passes the raw value it read). A bad value raises ParamError with one line naming the
parameter and what was given; the node logs it and exits with code 2."""

import math


class ParamError(ValueError):
    pass


def finite(name, value):
    """A finite int or float (not a bool, not text), as a float."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParamError(f"parameter {name} must be a number, got {value!r}")
    if not math.isfinite(value):
        raise ParamError(f"parameter {name} must be finite, got {value!r}")
    return float(value)


def positive(name, value):
    number = finite(name, value)
    if number <= 0:
        raise ParamError(f"parameter {name} must be > 0, got {value!r}")
    return number


def non_negative(name, value):
    number = finite(name, value)
    if number < 0:
        raise ParamError(f"parameter {name} must be >= 0, got {value!r}")
    return number


def count(name, value):
    """A whole number >= 0 (a count of tries): 2.5 is refused, not quietly cut to 2."""
    number = non_negative(name, value)
    if not number.is_integer():
        raise ParamError(f"parameter {name} must be a whole number, got {value!r}")
    return int(number)
