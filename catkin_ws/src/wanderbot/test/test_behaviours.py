"""The chapter 7 state machines, driven with injected times."""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from wanderbot.behaviours import TrafficLight, Wanderer  # noqa: E402


def run_light(start, seconds, dt=0.1):
    light = TrafficLight(start, period=3.0)
    steps = int(round(seconds / dt))
    return [(start + i * dt, light.update(start + i * dt)) for i in range(steps)]


def test_traffic_light_turns_green_at_once_then_alternates_every_3_s():
    samples = run_light(100.0, 12.55)
    changes = [t for (t, d), (_, prev) in zip(samples[1:], samples, strict=False) if d != prev]
    assert samples[0][1] is True
    assert changes == pytest.approx([103.0, 106.0, 109.0, 112.0], abs=1e-6)


def test_traffic_light_share_of_driving_is_half():
    samples = run_light(0.0, 60.0)
    share = sum(1 for _, d in samples if d) / len(samples)
    assert share == pytest.approx(0.5, abs=0.02)


def test_wanderer_drives_until_obstacle_then_spins_5_s():
    w = Wanderer(0.0)
    assert w.update(0.1, 3.0) == Wanderer.DRIVE
    assert w.command(0.3, 1.0) == (0.3, 0.0)
    assert w.update(2.0, 0.79) == Wanderer.SPIN
    assert w.command(0.3, 1.0) == (0.0, 1.0)
    assert w.update(6.9, 0.5) == Wanderer.SPIN  # spins for the whole 5 s
    assert w.update(7.05, 3.0) == Wanderer.DRIVE


def test_wanderer_times_out_after_30_s_of_driving():
    w = Wanderer(0.0)
    assert w.update(29.9, 5.0) == Wanderer.DRIVE
    assert w.update(30.1, 5.0) == Wanderer.SPIN
    assert w.update(35.2, 5.0) == Wanderer.DRIVE
    assert w.update(65.1, 5.0) == Wanderer.DRIVE
    assert w.update(65.3, 5.0) == Wanderer.SPIN


def test_wanderer_treats_unknown_or_nan_range_as_blocked():
    assert Wanderer(0.0).update(0.1, None) == Wanderer.SPIN
    assert Wanderer(0.0).update(0.1, float("nan")) == Wanderer.SPIN
    assert Wanderer(0.0).update(0.1, float("inf")) == Wanderer.DRIVE


def test_wanderer_spins_again_when_still_blocked_after_spinning():
    w = Wanderer(0.0)
    w.update(1.0, 0.5)
    assert w.update(6.1, 0.5) == Wanderer.SPIN  # no forward command while blocked
    assert w.update(11.0, 3.0) == Wanderer.SPIN  # the second spin runs its full 5 s
    assert w.update(11.2, 3.0) == Wanderer.DRIVE


def test_traffic_light_keeps_alternating_after_time_jumps_back():
    # A simulator restart: the clock goes from 500 s back to 1 s.
    light = TrafficLight(490.0, period=3.0)
    for i in range(100):
        light.update(490.0 + i * 0.1)
    states = [light.update(1.0 + i * 0.1) for i in range(100)]
    changes = sum(1 for a, b in zip(states, states[1:], strict=False) if a != b)
    assert changes >= 3  # still flipping every 3 s of the new clock, not stuck till 500 s


def test_wanderer_keeps_its_timing_after_time_jumps_back():
    wanderer = Wanderer(400.0, min_range=0.8, drive_time=2.0, spin_time=1.0)
    for i in range(10):
        wanderer.update(400.0 + i * 0.1, 5.0)
    states = [wanderer.update(1.0 + i * 0.1, 5.0) for i in range(60)]
    assert Wanderer.SPIN in states and states[-1] in (Wanderer.DRIVE, Wanderer.SPIN)
    first_spin = states.index(Wanderer.SPIN)
    assert first_spin <= 21  # the drive phase is timed from the jump: about 2 s, not 400 s
