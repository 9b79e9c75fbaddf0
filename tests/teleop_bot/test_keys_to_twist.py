"""Each keys_to_twist variant fed real key messages on `keys`; Twists checked on `cmd_vel`."""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from teleop_helpers import SEND_KEYS, rate_hz, twists  # noqa: E402


def segments(samples):
    """Runs of equal (linear, angular): [(value, first time, last time, count)]."""
    runs = []
    for t, lin, ang in samples:
        value = (round(lin, 6), round(ang, 6))
        if runs and runs[-1][0] == value:
            runs[-1][2], runs[-1][3] = t, runs[-1][3] + 1
        else:
            runs.append([value, t, t, 1])
    return runs


def start_node(ros, script, *args):
    node = ros.start(["rosrun", "teleop_bot", script, *args], name=script)
    ros.wait_for_topic("cmd_vel")
    return node


def test_keys_to_twist_one_twist_per_known_key(ros):
    start_node(ros, "keys_to_twist.py")
    probe = ros.probe(["cmd_vel"], duration=60)
    ros.run(SEND_KEYS + ["w@0", "q@0.2", "a@0.4", "d@0.6", "Z@0.8", "x@1.0", "s@1.2"], timeout=60)
    messages = probe.stop()
    values = [(lin, ang) for _, lin, ang in twists(messages)]
    # 'a' turns left: positive yaw rate (REP 103); q and Z are not driving keys.
    assert values == [(1.0, 0.0), (0.0, 1.0), (0.0, -1.0), (-1.0, 0.0), (0.0, 0.0)]


def test_using_rate_repeats_the_last_command_at_10_hz(ros):
    start_node(ros, "keys_to_twist_using_rate.py")
    probe = ros.probe(["cmd_vel"], duration=60)
    ros.run(SEND_KEYS + ["w@0.5", "a@2.5", "?@3.5", "s@4.5"], timeout=60)
    samples = twists(probe.stop())
    runs = segments(samples)
    assert [r[0] for r in runs] == [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.0, 0.0)]
    # w held for 2 s, a for 2 s (the unknown key changed nothing)
    assert runs[1][2] - runs[1][1] == pytest.approx(2.0, abs=0.3)
    assert runs[2][2] - runs[2][1] == pytest.approx(2.0, abs=0.3)
    assert rate_hz([t for t, _, _ in samples]) == pytest.approx(10.0, rel=0.15)


def test_parameterized_warns_and_defaults_to_a_tenth(ros):
    node = start_node(ros, "keys_to_twist_parameterized.py")
    probe = ros.probe(["cmd_vel"], duration=60)
    ros.run(SEND_KEYS + ["w@0", "a@1"], timeout=60)
    runs = segments(twists(probe.stop()))
    assert [r[0] for r in runs][-2:] == [(0.1, 0.0), (0.0, 0.1)]
    log = ros.output(node)
    assert "WARNING: linear scale not provided. Defaulting to 0.1" in log
    assert "WARNING: angular scale not provided. Defaulting to 0.1" in log


def test_parameterized_uses_the_scales_from_the_command_line(ros):
    node = start_node(
        ros, "keys_to_twist_parameterized.py", "_linear_scale:=0.5", "_angular_scale:=0.4"
    )
    probe = ros.probe(["cmd_vel"], duration=60)
    ros.run(SEND_KEYS + ["w@0", "d@1", "x@2"], timeout=60)
    samples = twists(probe.stop())
    assert [r[0] for r in segments(samples)][-3:] == [(0.5, 0.0), (0.0, -0.4), (-0.5, 0.0)]
    assert rate_hz([t for t, _, _ in samples]) == pytest.approx(10.0, rel=0.15)
    assert "not provided" not in ros.output(node)


def test_parameterized_launch_file_carries_the_book_values(ros):
    ros.start(["roslaunch", "teleop_bot", "keys_to_twist_parameterized.launch"], name="launch")
    ros.wait_for_topic("cmd_vel")
    probe = ros.probe(["cmd_vel"], duration=60)
    ros.run(SEND_KEYS + ["w@0", "a@1"], timeout=60)
    assert [r[0] for r in segments(twists(probe.stop()))][-2:] == [(0.5, 0.0), (0.0, 0.4)]


def test_bad_scale_is_a_clear_error(ros):
    done = ros.run(
        ["rosrun", "teleop_bot", "keys_to_twist_parameterized.py", "_linear_scale:=fast"],
        check=False,
    )
    assert done.returncode == 2
    assert "~linear_scale must be a number" in done.stdout + done.stderr


def test_ramps_limit_each_step_and_publish_at_20_hz(ros):
    node = ros.start(["roslaunch", "teleop_bot", "keys_to_twist_with_ramps.launch"], name="ramps")
    ros.wait_for_topic("cmd_vel")
    probe = ros.probe(["cmd_vel"], duration=60)
    ros.run(SEND_KEYS + ["w@0.5", "a@2.0", "x@3.5", "s@5.5"], timeout=60)
    samples = twists(probe.stop())
    times = [t for t, _, _ in samples]
    assert rate_hz(times) == pytest.approx(20.0, rel=0.15)
    linear_accel = angular_accel = 1.0  # from the launch file
    for (t0, l0, a0), (t1, l1, a1) in zip(samples, samples[1:], strict=False):
        dt = t1 - t0
        # the node steps by accel * (its own loop period); allow the probe's receive jitter
        assert abs(l1 - l0) <= linear_accel * (dt + 0.02) + 1e-9, (t0, l0, t1, l1)
        assert abs(a1 - a0) <= angular_accel * (dt + 0.02) + 1e-9, (t0, a0, t1, a1)
    linear = [lin for _, lin, _ in samples]
    angular = [ang for _, _, ang in samples]
    assert max(linear) == pytest.approx(0.5) and min(linear) == pytest.approx(-0.5)
    assert max(angular) == pytest.approx(1.0)
    # 0 -> 0.5 m/s at 1 m/s^2 takes 0.5 s: about 10 intermediate steps at 20 Hz
    rising = [v for v in linear if 0.0 < v < 0.5]
    assert len(rising) >= 7
    assert linear[-1] == 0.0 and angular[-1] == 0.0
    assert "not defined" not in ros.output(node)


def test_ramps_warn_for_missing_parameters(ros):
    node = start_node(ros, "keys_to_twist_with_ramps.py")
    ros.wait_for(lambda: "linear_accel" in ros.output(node), 20, "parameter warnings")
    log = ros.output(node)
    for line in (
        "parameter [~angular_scale] not defined. Defaulting to 0.100",
        "parameter [~linear_scale] not defined. Defaulting to 0.100",
        "parameter [~angular_accel] not defined. Defaulting to 1.000",
        "parameter [~linear_accel] not defined. Defaulting to 1.000",
    ):
        assert line in log
