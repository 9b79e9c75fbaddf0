"""The simulated Kobuki base: driving distance, walls and bumper, watchdog, bad commands,
the command mux, pause/step. Real roscore, real simulator node, sim time."""

import math
import time

from simkit import (
    DRIVE,
    drive,
    last_pose,
    publish_once,
    sim_time,
    start_simulator,
    wait_sim_seconds,
    wall_ahead,
    write_world,
)


def open_world(tmp_path):
    # A far wall only, so the world is valid and the robot has room.
    return write_world(tmp_path, "open", boxes=[(30, 0, 0, 1, 1, 1)])


def test_drive_half_metre_per_second_for_two_seconds_moves_one_metre(ros, tmp_path):
    # Real time: the driver's timing jitter then costs millimetres. A driver that stalls (a
    # loaded machine) holds the clock: with a lead of 1.5 of its 0.1 s periods, on-time
    # commands never wait, and a late stop adds at most 0.15 s at 0.5 m/s, within 0.08 m.
    start_simulator(ros, open_world(tmp_path), speed=1.0, wait_for_commands=0.15)
    drive(ros, 0.5, 0.0, 2.0)
    wait_sim_seconds(ros, 1.0)
    x, y, yaw, truth = last_pose(ros)
    ox, oy, _, odom = last_pose(ros, "odom")
    assert truth["header"]["frame_id"] == "world"
    assert odom["header"]["frame_id"] == "odom"
    assert odom["child_frame_id"] == "base_footprint"
    assert abs(x - 1.0) < 0.08, x
    assert abs(y) < 1e-6 and abs(yaw) < 1e-6
    assert abs(ox - x) < 1e-3 and abs(oy - y) < 1e-3  # odom_noise off: odom is exact


def test_odometry_drifts_by_default_but_not_absurdly(ros, tmp_path):
    start_simulator(ros, open_world(tmp_path), noise=True, seed=3)
    drive(ros, 0.5, 0.4, 6.0)
    wait_sim_seconds(ros, 1.0)
    x, y, yaw, _ = last_pose(ros)
    ox, oy, oyaw, odom = last_pose(ros, "odom")
    error = math.hypot(ox - x, oy - y)
    assert 1e-4 < error < 0.3, (x, y, ox, oy)
    assert odom["pose"]["covariance"][0] > 0


def test_robot_stops_at_wall_with_bumper_and_no_tunnelling(ros, tmp_path):
    # A thin (5 cm) wall 1.5 m ahead; full speed (0.7 m/s) for 5 s would cross it 2x over.
    start_simulator(ros, wall_ahead(tmp_path, 1.5, thickness=0.05))
    bumper = ros.probe(["mobile_base/events/bumper"], count=1, timeout=60)
    drive(ros, 0.7, 0.0, 5.0)
    events = bumper.wait(30)
    x, _, _, _ = last_pose(ros)
    assert x <= 1.5 - 0.18 + 1e-3, x
    assert x > 1.5 - 0.18 - 0.02, x
    assert events and events[0]["msg"] == {"bumper": 1, "state": 1}  # CENTER PRESSED
    # Backing off works and releases the bumper.
    released = ros.probe(["mobile_base/events/bumper"], count=1, timeout=60)
    drive(ros, -0.3, 0.0, 1.0)
    assert released.wait(30)[0]["msg"] == {"bumper": 1, "state": 0}
    assert last_pose(ros)[0] < x - 0.1


def test_watchdog_stops_the_robot_after_0_6_s(ros, tmp_path):
    start_simulator(ros, open_world(tmp_path))
    drive(ros, 0.3, 0.0, 0.3, stop=False)  # a few commands, then silence
    wait_sim_seconds(ros, 2.0)
    x1, _, _, msg = last_pose(ros)
    assert msg["twist"]["twist"]["linear"]["x"] == 0.0
    # Driven for 0.3 s plus at most 0.6 s of watchdog (and the ramps): about 0.1-0.3 m.
    assert 0.05 < x1 < 0.35, x1
    wait_sim_seconds(ros, 2.0)
    assert last_pose(ros)[0] == x1  # no creeping at rest


def test_nan_inf_and_huge_commands_are_rejected_with_a_warning(ros, tmp_path):
    sim = start_simulator(ros, open_world(tmp_path))
    before = last_pose(ros)[:3]
    for value in ("nan", "inf", "1e9"):
        publish_once(ros, "cmd_vel_mux/input/teleop", linear=value)
    publish_once(ros, "mobile_base/commands/velocity", angular="-inf")
    # Each reason is warned about (throttled per reason, so one cannot hide the other).
    for text in (
        "Rejected velocity command on cmd_vel_mux/input/teleop",
        "NaN or infinite",
        "beyond the plausible limits",
    ):
        ros.wait_for(lambda text=text: text in ros.output(sim), 30, repr(text))
    wait_sim_seconds(ros, 1.0)
    assert last_pose(ros)[:3] == before
    # A valid command still works afterwards.
    drive(ros, 0.3, 0.0, 1.0)
    assert last_pose(ros)[0] > before[0] + 0.1


def test_plain_cmd_vel_is_ignored_with_a_hint_naming_the_remap(ros, tmp_path):
    sim = start_simulator(ros, open_world(tmp_path))
    publish_once(ros, "cmd_vel", linear=0.5)
    wait_sim_seconds(ros, 1.0)
    assert last_pose(ros)[0] == 0.0
    ros.wait_for(lambda: "cmd_vel:=cmd_vel_mux/input/teleop" in ros.output(sim), 10, "warning")


def test_mux_priorities_teleop_over_navi(ros, tmp_path):
    start_simulator(ros, open_world(tmp_path), speed=2.0)
    navi = ros.start(
        ["/usr/bin/python3", str(DRIVE), "--topic=cmd_vel_mux/input/navi", "--linear=0.3"]
        + ["--seconds=100000"]  # until stopped: a loaded machine may take long to get to x2
    )
    ros.wait_for(lambda: last_pose(ros)[0] > 0.2, 60, "navi to drive the robot")
    # Teleop (priority 7) turning in place overrides navi (priority 5)...
    drive(ros, 0.0, 1.5, 3.0)
    x1, y1, yaw1, _ = last_pose(ros)
    assert abs(yaw1) > 1.0, yaw1
    # ...and once teleop has been silent for its 1 s timeout, navi drives again.
    wait_sim_seconds(ros, 3.0)
    x2, y2, _, _ = last_pose(ros)
    assert math.hypot(x2 - x1, y2 - y1) > 0.3
    ros.stop(navi)


def test_pause_and_step(ros, tmp_path):
    start_simulator(ros, open_world(tmp_path), start_paused="true")
    t0 = sim_time(ros)
    assert t0 >= 1.0  # /clock starts at 1.0 s, never 0
    ros.run(["rosservice", "call", "/simulator/step"])
    ros.run(["rosservice", "call", "/simulator/step"])
    assert abs(sim_time(ros) - (t0 + 0.02)) < 1e-6
    ros.run(["rosservice", "call", "/simulator/unpause"])
    wait_sim_seconds(ros, 0.5)
    ros.run(["rosservice", "call", "/simulator/pause"])
    t1 = sim_time(ros)
    time.sleep(0.5)
    assert sim_time(ros) == t1


def test_set_pose_teleports_and_refuses_obstacles(ros, tmp_path):
    sim = start_simulator(ros, wall_ahead(tmp_path, 3.0))
    # Latched until its effect is seen (`-1` latches for 3 s only, which a loaded machine's
    # connection can take longer than).
    pub = ["rostopic", "pub", "/simulator/set_pose", "geometry_msgs/Pose2D"]
    teleport = ros.start([*pub, "{x: 1.0, y: 2.0, theta: 1.0}"])
    ros.wait_for(lambda: last_pose(ros)[:2] == (1.0, 2.0), 60, "the robot at (1, 2)")
    ros.stop(teleport)
    assert abs(last_pose(ros)[2] - 1.0) < 1e-6
    teleport = ros.start([*pub, "{x: 3.5, y: 0.0, theta: 0.0}"])  # inside the wall
    ros.wait_for(lambda: "inside an obstacle" in ros.output(sim), 60, "a warning")
    ros.stop(teleport)
    assert last_pose(ros)[:2] == (1.0, 2.0)
    teleport = ros.start([*pub, "{x: 1.0e+300, y: 0.0, theta: 0.0}"])  # beyond Bullet's reach
    ros.wait_for(lambda: "within 1e6 of the origin" in ros.output(sim), 60, "a warning")
    ros.stop(teleport)
    assert last_pose(ros)[:2] == (1.0, 2.0)
