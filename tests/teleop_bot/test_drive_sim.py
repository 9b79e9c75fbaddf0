"""Keys in, the simulated Turtlebot moves as commanded (checked on ground truth)."""

import math
import os
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "wanderbot"))
from teleop_helpers import lockstep, start_in_terminal  # noqa: E402
from wander_sim import poses, start_sim, write_room  # noqa: E402

TRUTH = "base_pose_ground_truth"


def unwrap(yaws):
    out = [yaws[0]]
    for y in yaws[1:]:
        out.append(out[-1] + math.remainder(y - out[-1], 2 * math.pi))
    return out


PHYSICS_RATE = 100  # the simulator's default physics steps per sim second


def stepping_clock(ros, gate, period, ticks, *options, pass_fds=()):
    """A lock-step clock that steps the paused simulator one tick (`period` s) at a time,
    each tick once the teleop node has published on `gate` (lockstep.py)."""
    steps = ["--step-service", "/simulator/step", "--steps-per-tick", round(period * PHYSICS_RATE)]
    return lockstep.start(ros, gate, period, ticks, *steps, *options, pass_fds=pass_fds)


def truth_until(ros, probe, clock):
    """Ground-truth poses up to the clock's last tick (waits until the probe has it)."""
    records = lockstep.finish(ros, clock)
    last = records[-1]["clock"]

    def stamps():
        return [m["msg"]["header"]["stamp"] for m in probe.messages()]

    ros.wait_for(lambda: stamps() and max(stamps()) >= last, 60, "the last ground truth")
    return [p for p in poses(probe.stop()) if p[0] <= last]


def test_keys_to_twist_with_ramps_drives_forward_then_turns_left(ros, tmp_path):
    # Sim time, stepped in lock step with the 20 Hz node: the keys go in at sim times.
    world, _ = write_room(tmp_path, width=8.0, height=8.0, start=(2.0, 4.0, 0.0))
    start_sim(ros, world=str(world), speed=1.0, seed=1)
    probe = ros.probe([TRUTH], duration=300, timeout=300)
    keys = ["w@0.5", "s@4.5", "a@6.0", "s@8.0"]
    clock = stepping_clock(
        ros, "cmd_vel_mux/input/teleop", 0.05, 190, *[f"--say=keys={k}" for k in keys]
    )
    ros.start(
        [
            "roslaunch",
            "teleop_bot",
            "keys_to_twist_with_ramps.launch",
            "cmd_vel:=cmd_vel_mux/input/teleop",
        ],
        name="ramps",
    )
    truth = truth_until(ros, probe, clock)
    _, x0, y0, _ = truth[0]
    _, x1, y1, _ = truth[-1]
    yaws = unwrap([s[3] for s in truth])
    # w for 4 s at 0.5 m/s (ramped at 1 m/s^2 by the node and the base: 1.88 m measured),
    # then a left turn in place for 2 s at 1 rad/s (2.0 rad). A key takes effect 0 to 1 + 2
    # ticks late (lockstep.SLACK_TICKS): a hold can be 0.15 s longer or shorter than
    # measured, +-0.075 m at 0.5 m/s and +-0.15 rad at 1 rad/s, twice for safety.
    assert 1.73 <= x1 - x0 <= 2.03, (x0, x1)
    assert abs(y1 - y0) < 0.05
    turned = yaws[-1] - yaws[0]
    assert 1.7 <= turned <= 2.3, turned  # 'a' = positive yaw rate = left (REP 103)


@pytest.mark.skipif(not os.path.exists("/dev/ptmx"), reason="no pseudo-terminals")
def test_keyboard_teleop_launch_drives_the_robot(ros, tmp_path):
    world, _ = write_room(tmp_path, width=8.0, height=8.0, start=(2.0, 4.0, 0.0))
    start_sim(ros, world=str(world), speed=1.0, seed=1)
    proc, master, _ = start_in_terminal(
        ros, ["roslaunch", "teleop_bot", "keyboard_teleop.launch"], "keyboard_teleop"
    )
    probe = ros.probe([TRUTH], duration=300, timeout=300)
    # 'i' held (repeated every tick) for 4 s of sim time: 0.2 m/s after 1 s; then released,
    # the robot stops smoothly.
    typing = ["--tty-fd", master, "--type=i@0.5-4.5"]
    clock = stepping_clock(ros, "cmd_vel_mux/input/teleop", 0.1, 65, *typing, pass_fds=(master,))
    truth = truth_until(ros, probe, clock)
    travelled = truth[-1][1] - truth[0][1]
    # 0.94 m measured; the first and last i take effect 0 to 1 + 2 ticks (0.3 s) late:
    # +-0.06 m at 0.2 m/s, twice for safety.
    assert 0.82 <= travelled <= 1.06, travelled
    assert abs(truth[-1][2] - truth[0][2]) < 0.05
    still = [s for s in truth if s[0] >= truth[-1][0] - 0.5]
    assert still[-1][1] - still[0][1] < 0.02  # stopped at the end
    os.write(master, b"\x03")
    proc.wait(timeout=60)
