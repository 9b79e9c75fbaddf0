"""Each keys_to_twist variant fed real key messages on `keys`; Twists checked on `cmd_vel`.

The variants that publish at a rate run on sim time with a lock-step clock (lockstep.py): keys
go in at given sim times, and rates and durations are counted in ticks of that clock."""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from teleop_helpers import (  # noqa: E402
    SEND_KEYS,
    clock_twists,
    lockstep,
    ticks_between,
    twists,
)

SLACK = lockstep.SLACK_TICKS


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


def run_on_lockstep(ros, cmd, period, ticks, *keys):
    """Start `cmd` on sim time with a lock-step clock that says `keys` (KEY@T[/ECHOES]) on
    `keys`; returns the clock's records once its last tick is done."""
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    says = [f"--say=keys={key}" for key in keys]
    clock = lockstep.start(ros, "cmd_vel", period, ticks, *says)
    node = ros.start(cmd, name=Path(cmd[2]).name)
    return node, lockstep.finish(ros, clock)


def wait_for_values(ros, probe, values, what):
    """Wait until the probe's Twists end with the runs `values`; return its samples."""

    def arrived():
        runs = [r[0] for r in segments(twists(probe.messages()))]
        return runs[-len(values) :] == values

    ros.wait_for(arrived, 60, what)
    return twists(probe.stop())


def test_keys_to_twist_one_twist_per_known_key(ros):
    start_node(ros, "keys_to_twist.py")
    probe = ros.probe(["cmd_vel"], count=5, timeout=90)
    keys = ["w@0/1", "q@0.2", "a@0.4/1", "d@0.6/1", "Z@0.8", "x@1.0/1", "s@1.2/1"]
    ros.run(SEND_KEYS + ["--ack", "cmd_vel", *keys], timeout=120)
    values = [(lin, ang) for _, lin, ang in twists(probe.wait(100))]
    # 'a' turns left: positive yaw rate (REP 103); q and Z are not driving keys.
    assert values == [(1.0, 0.0), (0.0, 1.0), (0.0, -1.0), (-1.0, 0.0), (0.0, 0.0)]


def test_using_rate_repeats_the_last_command_at_10_hz(ros):
    # Each known key is answered at once (one more Twist), then repeated every 0.1 s.
    cmd = ["rosrun", "teleop_bot", "keys_to_twist_using_rate.py"]
    keys = ["w@0.5/1", "a@2.5/1", "?@3.5", "s@4.5/1"]
    _, records = run_on_lockstep(ros, cmd, 0.1, 55, *keys)
    runs = segments(clock_twists(records))
    assert [r[0] for r in runs] == [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.0, 0.0)]
    # w held for 2 s, a for 2 s (the unknown key changed nothing): the answer + 20 repeats
    for value, first, last, count in runs[1:3]:
        assert abs(count - 21) <= SLACK, (value, count)
        assert last - first == pytest.approx(2.0, abs=SLACK * 0.1 + 1e-6), value
    # 10 Hz: one Twist a tick from the first key to the last, plus the three answers
    assert abs(ticks_between(records, 6, 45) - (40 + 2)) <= SLACK


def test_parameterized_warns_and_defaults_to_a_tenth(ros):
    node = start_node(ros, "keys_to_twist_parameterized.py")
    probe = ros.probe(["cmd_vel"], duration=90, timeout=90)
    ros.run(SEND_KEYS + ["w@0", "a@1"], timeout=60)
    wait_for_values(ros, probe, [(0.1, 0.0), (0.0, 0.1)], "w then a, scaled by 0.1")
    log = ros.output(node)
    assert "WARNING: linear scale not provided. Defaulting to 0.1" in log
    assert "WARNING: angular scale not provided. Defaulting to 0.1" in log


def test_parameterized_uses_the_scales_from_the_command_line(ros):
    cmd = ["rosrun", "teleop_bot", "keys_to_twist_parameterized.py"]
    cmd += ["_linear_scale:=0.5", "_angular_scale:=0.4"]
    node, records = run_on_lockstep(ros, cmd, 0.1, 35, "w@0.5/1", "d@1.5/1", "x@2.5/1")
    runs = segments(clock_twists(records))
    assert [r[0] for r in runs][-3:] == [(0.5, 0.0), (0.0, -0.4), (-0.5, 0.0)]
    # 10 Hz: one Twist a tick, plus the answer to each key
    assert abs(ticks_between(records, 6, 35) - (30 + 2)) <= SLACK
    assert "not provided" not in ros.output(node)


def test_parameterized_launch_file_carries_the_book_values(ros):
    ros.start(["roslaunch", "teleop_bot", "keys_to_twist_parameterized.launch"], name="launch")
    ros.wait_for_topic("cmd_vel")
    probe = ros.probe(["cmd_vel"], duration=90, timeout=90)
    ros.run(SEND_KEYS + ["w@0", "a@1"], timeout=60)
    wait_for_values(ros, probe, [(0.5, 0.0), (0.0, 0.4)], "w then a, scaled 0.5 and 0.4")


def test_bad_scale_is_a_clear_error(ros):
    done = ros.run(
        ["rosrun", "teleop_bot", "keys_to_twist_parameterized.py", "_linear_scale:=fast"],
        check=False,
    )
    assert done.returncode == 2
    assert "~linear_scale must be a number" in done.stderr + done.stdout


def test_ramps_limit_each_step_and_publish_at_20_hz(ros):
    cmd = ["roslaunch", "teleop_bot", "keys_to_twist_with_ramps.launch"]
    period = 0.05
    keys = ["w@0.5", "a@2.0", "x@3.5", "s@5.5"]
    node, records = run_on_lockstep(ros, cmd, period, 140, *keys)
    samples = clock_twists(records)
    # 20 Hz: one Twist a tick (the ramps answer no key at once)
    assert abs(ticks_between(records, 5, 140) - 136) <= SLACK
    linear_accel = angular_accel = 1.0  # from the launch file
    for (t0, l0, a0), (t1, l1, a1) in zip(samples, samples[1:], strict=False):
        # the node steps by accel * (the sim time since its last step): at most the ticks
        # between them, give or take the clock's slack
        dt = t1 - t0 + SLACK * period + 1e-9
        assert abs(l1 - l0) <= linear_accel * dt, (t0, l0, t1, l1)
        assert abs(a1 - a0) <= angular_accel * dt, (t0, a0, t1, a1)
    # Each step spans whole ticks of sim time: every value is a multiple of accel * period.
    for _, lin, ang in samples:
        for steps in (lin / (linear_accel * period), ang / (angular_accel * period)):
            assert steps == pytest.approx(round(steps), abs=1e-6), (lin, ang)
    linear = [lin for _, lin, _ in samples]
    angular = [ang for _, _, ang in samples]
    assert max(linear) == pytest.approx(0.5) and min(linear) == pytest.approx(-0.5)
    assert max(angular) == pytest.approx(1.0)
    # 0 -> 0.5 m/s at 1 m/s^2 takes 0.5 s of sim time
    rise_start = max(t for t, lin, _ in samples if lin == 0.0 and t < 2.0 + 1000.0)
    rise_end = min(t for t, lin, _ in samples if lin == pytest.approx(0.5))
    assert rise_end - rise_start >= 0.5 - SLACK * period - 1e-6
    assert linear[-1] == 0.0 and angular[-1] == 0.0
    assert "not defined" not in ros.output(node)


def test_ramps_warn_for_missing_parameters(ros):
    node = start_node(ros, "keys_to_twist_with_ramps.py")
    ros.wait_for(lambda: "linear_accel" in ros.output(node), 60, "parameter warnings")
    log = ros.output(node)
    for line in (
        "parameter [~angular_scale] not defined. Defaulting to 0.100",
        "parameter [~linear_scale] not defined. Defaulting to 0.100",
        "parameter [~angular_accel] not defined. Defaulting to 1.000",
        "parameter [~linear_accel] not defined. Defaulting to 1.000",
    ):
        assert line in log
