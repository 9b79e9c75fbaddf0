"""The turtlebot_teleop key layout and its smoothing, with injected times."""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from teleop_bot.keyboard_teleop import HELP, KeyboardTeleop  # noqa: E402


def drive(teleop, seconds, t0=0.0, dt=0.1, key=None):
    out = []
    steps = int(round(seconds / dt))
    for i in range(1, steps + 1):
        t = t0 + i * dt
        if key:
            teleop.on_key(key, t)
        out.append(teleop.step(t, dt))
    return out


def test_help_text_matches_the_book():
    for line in ("Control Your Turtlebot!", "   u    i    o", "q/z : increase/decrease max speeds"):
        assert line in HELP
    assert "space key, k : force stop" in HELP and "CTRL-C to quit" in HELP


def test_i_ramps_up_to_speed_and_holding_it_keeps_going():
    t = KeyboardTeleop(speed=0.2, turn=1.0, linear_accel=0.2, angular_accel=1.0)
    out = drive(t, 3.0, key="i")
    assert out[0] == pytest.approx((0.02, 0.0))
    assert out[-1] == pytest.approx((0.2, 0.0))
    diffs = [b[0] - a[0] for a, b in zip(out, out[1:], strict=False)]
    assert max(diffs) <= 0.02 + 1e-9


def test_directions_follow_rep103():
    for key, sign in (("j", 1), ("l", -1), ("u", 1), ("o", -1)):
        t = KeyboardTeleop()
        assert drive(t, 2.0, key=key)[-1][1] == pytest.approx(sign * 1.0)
    t = KeyboardTeleop()
    assert drive(t, 2.0, key=",")[-1] == pytest.approx((-0.2, 0.0))


def test_released_key_stops_smoothly_after_timeout():
    t = KeyboardTeleop(key_timeout=0.75)
    drive(t, 2.0, key="i")
    out = drive(t, 2.0, t0=2.0)
    assert out[5][0] == pytest.approx(0.2)  # still within the timeout
    assert out[-1] == (0.0, 0.0)
    assert min(out[i][0] - out[i + 1][0] for i in range(len(out) - 1)) >= -1e-9


def test_space_and_k_force_stop_other_keys_stop_smoothly():
    for key in (" ", "k"):
        t = KeyboardTeleop()
        drive(t, 2.0, key="i")
        t.on_key(key, 2.0)
        assert t.step(2.1, 0.1) == (0.0, 0.0)
    t = KeyboardTeleop()
    drive(t, 2.0, key="i")
    t.on_key("p", 2.0)
    assert t.step(2.1, 0.1) == pytest.approx((0.18, 0.0))


def test_speed_keys_change_max_speeds_by_ten_percent():
    t = KeyboardTeleop(speed=0.2, turn=1.0)
    assert "speed 0.22\tturn 1.1" in t.on_key("q", 0.0)
    t.on_key("z", 0.0)
    assert (t.speed, t.turn) == pytest.approx((0.198, 0.99))
    t = KeyboardTeleop(speed=0.2, turn=1.0)
    t.on_key("w", 0.0)
    t.on_key("c", 0.0)
    assert (t.speed, t.turn) == pytest.approx((0.22, 0.9))
    t.on_key("x", 0.0)
    t.on_key("e", 0.0)
    assert (t.speed, t.turn) == pytest.approx((0.198, 0.99))


def test_help_repeats_every_15_speed_changes_and_ctrl_c_quits():
    t = KeyboardTeleop()
    texts = [t.on_key("q", 0.0) for _ in range(15)]
    assert "Control Your Turtlebot!" in texts[-1]
    assert all("Control" not in s for s in texts[:-1])
    t.on_key("\x03", 0.0)
    assert t.quit
