"""The shared parameter checks: one line naming the parameter and the value given."""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from rosbook_env.params import ParamError, count, finite, non_negative, positive  # noqa: E402


def test_good_values_come_back_as_floats():
    assert positive("~x", 2) == 2.0
    assert finite("~x", -0.5) == -0.5
    assert non_negative("~x", 0) == 0.0


@pytest.mark.parametrize("bad", ["fast", float("nan"), float("inf"), True, None])
def test_what_is_not_a_finite_number_is_refused_by_every_check(bad):
    for check in (finite, positive, non_negative):
        with pytest.raises(ParamError, match="parameter ~x must be"):
            check("~x", bad)


def test_bounds_name_the_value_given():
    with pytest.raises(ParamError, match=r"~x must be > 0, got 0"):
        positive("~x", 0)
    with pytest.raises(ParamError, match=r"~x must be >= 0, got -1.5"):
        non_negative("~x", -1.5)


def test_a_count_is_a_whole_number_of_zero_or_more():
    assert count("~n", 3) == 3 and count("~n", 2.0) == 2 and count("~n", 0) == 0
    for bad, says in [(2.5, "whole number"), (-1, ">= 0"), ("3", "a number"), (True, "a number")]:
        with pytest.raises(ParamError, match=says):
            count("~n", bad)
