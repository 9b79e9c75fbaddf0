"""key_publisher and keyboard_teleop driven through a real pseudo-terminal."""

import os
import subprocess
import sys
import termios
import time
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from teleop_helpers import (  # noqa: E402
    clock_twists,
    lockstep,
    start_in_terminal,
    ticks_between,
)

SLACK = lockstep.SLACK_TICKS


def type_keys(master, keys, hz=0.0):
    for key in keys:
        os.write(master, key.encode())
        if hz:
            time.sleep(1.0 / hz)


def wait_exit(proc, timeout=60):
    try:
        return proc.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        pytest.fail(f"{proc.label} did not exit after Ctrl-C")


def test_key_publisher_publishes_each_key_and_restores_the_terminal(ros):
    proc, master, slave = start_in_terminal(
        ros, ["rosrun", "teleop_bot", "key_publisher.py"], "key_publisher"
    )
    before = termios.tcgetattr(slave)
    assert before[3] & termios.ECHO and before[3] & termios.ICANON
    ros.wait_for_topic("keys")
    probe = ros.probe(["keys"], count=6, timeout=60)
    ros.wait_for(lambda: "Publishing keystrokes" in ros.output(proc), 60, "the banner")
    during = termios.tcgetattr(slave)
    assert not during[3] & termios.ICANON and not during[3] & termios.ECHO  # cbreak mode
    type_keys(master, "wasd!é", hz=20)  # no Enter needed
    assert [m["msg"]["data"] for m in probe.wait(70)] == list("wasd!é")
    os.write(master, b"\x03")  # Ctrl-C
    assert wait_exit(proc) == 0
    assert termios.tcgetattr(slave) == before


def test_key_publisher_restores_the_terminal_when_killed(ros):
    proc, master, slave = start_in_terminal(
        ros, ["rosrun", "teleop_bot", "key_publisher.py"], "key_publisher"
    )
    before = termios.tcgetattr(slave)
    ros.wait_for(lambda: "Publishing keystrokes" in ros.output(proc), 60, "the banner")
    assert termios.tcgetattr(slave) != before
    os.killpg(proc.pid, 15)  # SIGTERM, as from `kill` or a closing session manager
    wait_exit(proc)
    assert termios.tcgetattr(slave) == before


def test_key_publisher_without_a_terminal_says_so(ros):
    done = ros.run(["rosrun", "teleop_bot", "key_publisher.py"], check=False, input="wasd")
    assert done.returncode == 1
    assert "not a terminal" in done.stderr


def use_sim_time(ros):
    """Set before the node starts: a node that read use_sim_time false never subscribes to
    /clock, and the lock-step clock would wait for it in vain."""
    ros.run(["rosparam", "set", "/use_sim_time", "true"])


def typing_clock(ros, master, gate, ticks, *typing):
    """A lock-step clock (lockstep.py) on `gate`, 0.1 s a tick, that types into the terminal
    `master`: TEXT@T or TEXT@T1-T2 (every tick from T1 to T2, as a held key repeats).
    The node must have been started after use_sim_time(ros)."""
    options = ["--tty-fd", master] + [f"--type={t}" for t in typing]
    return lockstep.start(ros, gate, 0.1, ticks, *options, pass_fds=(master,))


def test_keyboard_teleop_prints_help_ramps_while_held_and_stops_when_released(ros):
    # Sim time on a lock-step clock that types the keys at given sim times: i held from 0.5 s
    # to 3 s (0.2 m/s needs 1 s at 0.2 m/s^2), released (stop smoothly 0.75 s after the last
    # i), j held from 5.5 s to 6.9 s, space (force stop) at 7 s, q at 8 s.
    keys = ["i@0.5-3.0", "j@5.5-6.9", " @7.0", "q@8.0"]
    use_sim_time(ros)
    proc, master, slave = start_in_terminal(
        ros, ["rosrun", "teleop_bot", "keyboard_teleop.py"], "keyboard_teleop"
    )
    before = termios.tcgetattr(slave)
    clock = typing_clock(ros, master, "cmd_vel", 90, *keys)
    ros.wait_for(lambda: "currently:" in ros.output(proc), 60, "the help text")
    out = ros.output(proc)
    for line in (
        "Control Your Turtlebot!",
        "   u    i    o",
        "   m    ,    .",
        "space key, k : force stop",
        "anything else : stop smoothly",
        "currently:\tspeed 0.2\tturn 1",
    ):
        assert line in out
    records = lockstep.finish(ros, clock)
    samples = clock_twists(records)
    # 10 Hz of sim time: one Twist a tick
    assert abs(ticks_between(records, 5, 90) - 86) <= SLACK
    linear = [lin for _, lin, _ in samples]
    angular = [ang for _, _, ang in samples]
    assert max(linear) == pytest.approx(0.2)
    assert max(angular) == pytest.approx(1.0)  # j turns left: positive (REP 103)
    assert min(linear) >= 0.0 and min(angular) >= 0.0
    for (t0, l0, a0), (t1, l1, a1) in zip(samples, samples[1:], strict=False):
        if a0 > 0.0 and a1 == 0.0:
            continue  # the space bar stops at once
        dt = t1 - t0 + SLACK * 0.1 + 1e-9  # sim time between its steps, within the slack
        assert abs(l1 - l0) <= 0.2 * dt and abs(a1 - a0) <= 1.0 * dt, (t0, t1)
        # each step spans whole ticks: multiples of accel * 0.1 s
        for steps in (l1 / 0.02, a1 / 0.1):
            assert steps == pytest.approx(round(steps), abs=1e-6), (t1, l1, a1)
    # Full speed from 1 s after the first i until 0.75 s after the last (3 s): 2.25 s, give
    # or take a tick for reading each key and the clock's slack.
    at_speed = [t for t, lin, _ in samples if lin == pytest.approx(0.2)]
    assert at_speed[-1] - at_speed[0] >= 2.25 - (2 + SLACK) * 0.1
    assert linear[-1] == 0.0 and angular[-1] == 0.0
    ros.wait_for(lambda: "speed 0.22\tturn 1.1" in ros.output(proc), 60, "q's new speeds")
    os.write(master, b"\x03")
    assert wait_exit(proc) == 0
    assert termios.tcgetattr(slave) == before


def test_keyboard_teleop_launch_reads_the_terminal_and_drives_the_mux_input(ros):
    use_sim_time(ros)
    proc, master, slave = start_in_terminal(
        ros, ["roslaunch", "teleop_bot", "keyboard_teleop.launch"], "keyboard_teleop_launch"
    )
    before = termios.tcgetattr(slave)
    # u held from 0.5 s to 2.5 s of sim time; 0.75 s later it would stop smoothly.
    clock = typing_clock(ros, master, "cmd_vel_mux/input/teleop", 30, "u@0.5-2.5")
    ros.wait_for(lambda: "Control Your Turtlebot!" in ros.output(proc), 60, "the help text")
    samples = clock_twists(lockstep.finish(ros, clock))
    # forward and left at full speed (0.2 m/s, 1 rad/s: reached after 1 s)
    assert samples[-1][1:] == (pytest.approx(0.2), pytest.approx(1.0))
    os.write(master, b"\x03")  # Ctrl-C reaches roslaunch, which stops the node
    wait_exit(proc, timeout=60)
    assert termios.tcgetattr(slave) == before


def test_keyboard_teleop_without_a_terminal_says_so(ros):
    done = ros.run(["rosrun", "teleop_bot", "keyboard_teleop.py"], check=False, input="")
    assert done.returncode == 1
    assert "not a terminal" in done.stderr
