"""Key mapping (REP 103 signs) and acceleration ramps."""

import math
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from teleop_bot.keys import velocities_for_key  # noqa: E402
from teleop_bot.ramps import ramped_twist, ramped_vel  # noqa: E402


def test_wxads_with_rep103_signs():
    assert velocities_for_key("w") == (1.0, 0.0)
    assert velocities_for_key("x") == (-1.0, 0.0)
    assert velocities_for_key("a") == (0.0, 1.0)  # left turn: positive yaw rate
    assert velocities_for_key("d") == (0.0, -1.0)
    assert velocities_for_key("s") == (0.0, 0.0)


def test_scales_and_first_character():
    assert velocities_for_key("w", 0.5, 0.4) == (0.5, 0.0)
    assert velocities_for_key("a", 0.5, 0.4) == (0.0, 0.4)
    assert velocities_for_key("wd", 0.5, 0.4) == (0.5, 0.0)


@pytest.mark.parametrize("key", ["", "q", "W", "\x1b", "é", " "])
def test_unknown_keys_are_ignored(key):
    assert velocities_for_key(key) is None


def test_ramp_steps_by_accel_times_dt_and_lands_on_target():
    v, steps = 0.0, []
    for _ in range(20):
        new = ramped_vel(v, 0.5, 0.05, 1.0)
        steps.append(new - v)
        v = new
    assert v == 0.5
    assert max(abs(s) for s in steps) <= 0.05 + 1e-12
    assert steps[:10] == pytest.approx([0.05] * 10)


def test_ramp_down_and_zero_or_bad_dt():
    assert ramped_vel(0.5, -0.5, 0.1, 1.0) == pytest.approx(0.4)
    assert ramped_vel(0.3, 0.0, 0.0, 1.0) == 0.3
    assert ramped_vel(0.3, 0.0, -1.0, 1.0) == 0.3
    assert ramped_vel(0.3, 0.0, math.nan, 1.0) == 0.3


def test_ramped_twist_uses_each_acceleration():
    assert ramped_twist((0.0, 0.0), (0.5, 1.0), 0.1, 1.0, 2.0) == pytest.approx((0.1, 0.2))
