"""Checking numeric node parameters (ROS-free: the caller passes the raw values)."""

import math


class ParamError(ValueError):
    pass


def positive_number(name, value):
    """A finite number > 0, or ParamError naming the parameter and what was given."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParamError(f"parameter {name} must be a number, got {value!r}")
    if not math.isfinite(value) or value <= 0:
        raise ParamError(f"parameter {name} must be finite and > 0, got {value!r}")
    return float(value)


def finite_number(name, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParamError(f"parameter {name} must be a number, got {value!r}")
    if not math.isfinite(value):
        raise ParamError(f"parameter {name} must be finite, got {value!r}")
    return float(value)
