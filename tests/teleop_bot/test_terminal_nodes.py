"""key_publisher and keyboard_teleop driven through a real pseudo-terminal."""

import os
import subprocess
import sys
import termios
import time
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from teleop_helpers import rate_hz, start_in_terminal, twists  # noqa: E402


def type_keys(master, keys, hz=0.0):
    for key in keys:
        os.write(master, key.encode())
        if hz:
            time.sleep(1.0 / hz)


def hold_key(master, key, seconds, hz=20.0):
    """A held key: the terminal's auto-repeat sends it again and again."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        os.write(master, key.encode())
        time.sleep(1.0 / hz)


def wait_exit(proc, timeout=15):
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
    probe = ros.probe(["keys"], count=6)
    ros.wait_for(lambda: "Publishing keystrokes" in ros.output(proc), 20, "the banner")
    during = termios.tcgetattr(slave)
    assert not during[3] & termios.ICANON and not during[3] & termios.ECHO  # cbreak mode
    type_keys(master, "wasd!é", hz=20)  # no Enter needed
    assert [m["msg"]["data"] for m in probe.wait(30)] == list("wasd!é")
    os.write(master, b"\x03")  # Ctrl-C
    assert wait_exit(proc) == 0
    assert termios.tcgetattr(slave) == before


def test_key_publisher_restores_the_terminal_when_killed(ros):
    proc, master, slave = start_in_terminal(
        ros, ["rosrun", "teleop_bot", "key_publisher.py"], "key_publisher"
    )
    before = termios.tcgetattr(slave)
    ros.wait_for(lambda: "Publishing keystrokes" in ros.output(proc), 30, "the banner")
    assert termios.tcgetattr(slave) != before
    os.killpg(proc.pid, 15)  # SIGTERM, as from `kill` or a closing session manager
    wait_exit(proc)
    assert termios.tcgetattr(slave) == before


def test_key_publisher_without_a_terminal_says_so(ros):
    done = ros.run(["rosrun", "teleop_bot", "key_publisher.py"], check=False, input="wasd")
    assert done.returncode == 1
    assert "not a terminal" in done.stderr


def test_keyboard_teleop_prints_help_ramps_while_held_and_stops_when_released(ros):
    proc, master, slave = start_in_terminal(
        ros, ["rosrun", "teleop_bot", "keyboard_teleop.py"], "keyboard_teleop"
    )
    before = termios.tcgetattr(slave)
    ros.wait_for_topic("cmd_vel")
    ros.wait_for(lambda: "currently:" in ros.output(proc), 20, "the help text")
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
    probe = ros.probe(["cmd_vel"], duration=60)
    time.sleep(0.5)
    hold_key(master, "i", 2.5)  # 0.2 m/s needs 1 s at 0.2 m/s^2
    time.sleep(2.5)  # released: stop smoothly after the 0.75 s key timeout
    hold_key(master, "j", 1.5)
    os.write(master, b" ")  # force stop
    time.sleep(1.0)
    type_keys(master, "q")
    time.sleep(0.5)
    samples = twists(probe.stop())
    assert rate_hz([t for t, _, _ in samples]) == pytest.approx(10.0, rel=0.15)
    linear = [lin for _, lin, _ in samples]
    angular = [ang for _, _, ang in samples]
    assert max(linear) == pytest.approx(0.2)
    assert max(angular) == pytest.approx(1.0)  # j turns left: positive (REP 103)
    assert min(linear) >= 0.0 and min(angular) >= 0.0
    for (t0, l0, a0), (t1, l1, a1) in zip(samples, samples[1:], strict=False):
        if a0 > 0.0 and a1 == 0.0:
            continue  # the space bar stops at once
        assert abs(l1 - l0) <= 0.2 * (t1 - t0 + 0.03) + 1e-9
        assert abs(a1 - a0) <= 1.0 * (t1 - t0 + 0.03) + 1e-9
    # held at full speed between the ramp-up and the release
    at_speed = [t for t, lin, _ in samples if lin == pytest.approx(0.2)]
    assert at_speed[-1] - at_speed[0] >= 1.2
    assert linear[-1] == 0.0 and angular[-1] == 0.0
    ros.wait_for(lambda: "speed 0.22\tturn 1.1" in ros.output(proc), 10, "q's new speeds")
    os.write(master, b"\x03")
    assert wait_exit(proc) == 0
    assert termios.tcgetattr(slave) == before


def test_keyboard_teleop_launch_reads_the_terminal_and_drives_the_mux_input(ros):
    proc, master, slave = start_in_terminal(
        ros, ["roslaunch", "teleop_bot", "keyboard_teleop.launch"], "keyboard_teleop_launch"
    )
    before = termios.tcgetattr(slave)
    ros.wait_for_topic("cmd_vel_mux/input/teleop", timeout=40)
    ros.wait_for(lambda: "Control Your Turtlebot!" in ros.output(proc), 20, "the help text")
    probe = ros.probe(["cmd_vel_mux/input/teleop"], duration=60)
    hold_key(master, "u", 2.0)
    samples = twists(probe.stop())
    assert samples[-1][1] == pytest.approx(0.2) and samples[-1][2] > 0.5  # forward + left
    os.write(master, b"\x03")  # Ctrl-C reaches roslaunch, which stops the node
    wait_exit(proc, timeout=30)
    assert termios.tcgetattr(slave) == before


def test_keyboard_teleop_without_a_terminal_says_so(ros):
    done = ros.run(["rosrun", "teleop_bot", "keyboard_teleop.py"], check=False, input="")
    assert done.returncode == 1
    assert "not a terminal" in done.stderr
