"""Checks for node parameters: a bad value gets a clear message, not a crash later."""

import math


class ParamError(ValueError):
    pass


def positive(name, value):
    number = _number(name, value)
    if number <= 0:
        raise ParamError(f"parameter {name} must be > 0, got {value!r}")
    return number


def non_negative(name, value):
    number = _number(name, value)
    if number < 0:
        raise ParamError(f"parameter {name} must be >= 0, got {value!r}")
    return number


def count(name, value):
    """A whole number >= 0 (a count of tries): 2.5 is refused, not quietly cut to 2."""
    number = non_negative(name, value)
    if not number.is_integer():
        raise ParamError(f"parameter {name} must be a whole number, got {value!r}")
    return int(number)


def _number(name, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParamError(f"parameter {name} must be a number, got {value!r}")
    if not math.isfinite(value):
        raise ParamError(f"parameter {name} must be finite, got {value!r}")
    return float(value)
