"""Keys in, the simulated Turtlebot moves as commanded (checked on ground truth)."""

import math
import os
import sys
import time
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "wanderbot"))
from teleop_helpers import SEND_KEYS, start_in_terminal  # noqa: E402
from wander_sim import poses, start_sim, unpause, write_room  # noqa: E402

TRUTH = "base_pose_ground_truth"


def unwrap(yaws):
    out = [yaws[0]]
    for y in yaws[1:]:
        out.append(out[-1] + math.remainder(y - out[-1], 2 * math.pi))
    return out


def test_keys_to_twist_with_ramps_drives_forward_then_turns_left(ros, tmp_path):
    # Real time, so the keys' wall-clock timing is the robot's timing.
    world, _ = write_room(tmp_path, width=8.0, height=8.0, start=(2.0, 4.0, 0.0))
    start_sim(ros, world=str(world), speed=1.0, seed=1)
    ros.start(
        [
            "roslaunch",
            "teleop_bot",
            "keys_to_twist_with_ramps.launch",
            "cmd_vel:=cmd_vel_mux/input/teleop",
        ],
        name="ramps",
    )
    ros.wait_for_topic("cmd_vel_mux/input/teleop")
    probe = ros.probe([TRUTH], duration=120, timeout=120)
    unpause(ros)
    ros.run(SEND_KEYS + ["w@0.5", "s@4.5", "a@6.0", "s@8.0"], timeout=60)
    time.sleep(1.5)
    truth = poses(probe.stop())
    _, x0, y0, _ = truth[0]
    _, x1, y1, _ = truth[-1]
    yaws = unwrap([s[3] for s in truth])
    # w for 4 s at 0.5 m/s (ramped at 1 m/s^2: about 1.75 m), then a left turn in place
    assert 1.3 <= x1 - x0 <= 2.2, (x0, x1)
    assert abs(y1 - y0) < 0.1
    turned = yaws[-1] - yaws[0]
    assert 1.0 <= turned <= 2.4, turned  # 'a' = positive yaw rate = left (REP 103)


@pytest.mark.skipif(not os.path.exists("/dev/ptmx"), reason="no pseudo-terminals")
def test_keyboard_teleop_launch_drives_the_robot(ros, tmp_path):
    world, _ = write_room(tmp_path, width=8.0, height=8.0, start=(2.0, 4.0, 0.0))
    start_sim(ros, world=str(world), speed=1.0, seed=1)
    proc, master, _ = start_in_terminal(
        ros, ["roslaunch", "teleop_bot", "keyboard_teleop.launch"], "keyboard_teleop"
    )
    ros.wait_for_topic("cmd_vel_mux/input/teleop", timeout=60)
    probe = ros.probe([TRUTH], duration=120, timeout=120)
    unpause(ros)
    end = time.monotonic() + 4.0
    while time.monotonic() < end:  # hold 'i' (auto-repeat) for 4 s: 0.2 m/s after 1 s
        os.write(master, b"i")
        time.sleep(0.05)
    time.sleep(2.0)  # released: the robot stops smoothly
    truth = poses(probe.stop())
    travelled = truth[-1][1] - truth[0][1]
    assert 0.5 <= travelled <= 1.15, travelled  # about 0.95 m expected
    assert abs(truth[-1][2] - truth[0][2]) < 0.05
    still = [s for s in truth if s[0] >= truth[-1][0] - 0.5]
    assert still[-1][1] - still[0][1] < 0.02  # stopped at the end
    os.write(master, b"\x03")
    proc.wait(timeout=30)
