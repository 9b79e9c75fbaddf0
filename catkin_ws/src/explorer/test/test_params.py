"""The parameter checks the explorer and move_base_lite share."""

import pytest
from explorer.params import ParamError, count, non_negative, positive


def test_a_count_is_a_whole_number_of_zero_or_more():
    assert count("~n", 3) == 3 and count("~n", 2.0) == 2 and count("~n", 0) == 0
    for bad, says in [(2.5, "whole number"), (-1, ">= 0"), ("3", "a number"), (True, "a number")]:
        with pytest.raises(ParamError, match=says):
            count("~n", bad)


def test_positive_and_non_negative_name_the_parameter_and_value():
    with pytest.raises(ParamError, match=r"~r must be > 0, got 0"):
        positive("~r", 0)
    with pytest.raises(ParamError, match=r"~r must be finite, got nan"):
        non_negative("~r", float("nan"))
