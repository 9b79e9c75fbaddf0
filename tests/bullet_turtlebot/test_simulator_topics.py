"""The simulator's published data: rates in sim time, LaserScan geometry (REP 117), ranges
against a known wall, tf, cameras (REP 118). Real roscore and simulator node."""

import math
import struct
import time

from simkit import (
    call_service,
    publish_once,
    ranges,
    secs,
    sim_time,
    start_simulator,
    wall_ahead,
    write_pgm,
)

CAMERA_X = -0.087  # camera_depth_frame in base_footprint


def rate(records, topic):
    """Publication rate from the stamps' typical spacing (robust to a loaded probe
    dropping a message now and then)."""
    stamps = [
        secs(r["msg"]["header"]["stamp"] if topic != "/clock" else r["msg"]["clock"])
        for r in records
        if r["topic"] == topic
    ]
    assert len(stamps) > 5, topic
    deltas = sorted(b - a for a, b in zip(stamps, stamps[1:], strict=False))
    assert deltas[0] > 0, f"{topic}: stamps not increasing"
    return 1.0 / deltas[len(deltas) // 2], stamps


def test_rates_in_sim_time_and_stamps(ros, tmp_path):
    # Real time here, so that the Python probe keeps up with 100 clock messages per second.
    start_simulator(ros, wall_ahead(tmp_path, 3.0), speed=1.0)
    topics = ["/scan", "/odom", "/clock", "/base_pose_ground_truth"]
    started = time.time()  # whatever the probe receives was published after this
    probe = ros.probe(topics, duration=300, timeout=300)

    def clocks_so_far():
        return [secs(r["msg"]["clock"]) for r in probe.messages() if r["topic"] == "/clock"]

    # 3 s of sim time (30 scans, 150 odometry messages), however long it takes; then pause
    # (the paused simulator repeats its time: the probe then has the clock's last value).
    ros.wait_for(
        lambda: max(clocks_so_far(), default=0) - min(clocks_so_far(), default=0) >= 3.0,
        120,
        "3 s of sim time",
    )
    call_service(ros, "/simulator/pause")
    ros.wait_for(lambda: len(set(clocks_so_far()[-2:])) == 1, 60, "the paused clock")
    records = probe.stop()
    final_clock = clocks_so_far()[-1]
    running = [
        r for r in records if r["topic"] != "/clock" or secs(r["msg"]["clock"]) < final_clock
    ]
    scan_hz, scan_stamps = rate(running, "/scan")
    odom_hz, _ = rate(running, "/odom")
    clock_hz, clocks = rate(running, "/clock")
    truth_hz, _ = rate(running, "/base_pose_ground_truth")
    assert abs(scan_hz - 10) < 0.1
    assert abs(odom_hz - 50) < 0.5 and abs(truth_hz - 50) < 0.5
    assert abs(clock_hz - 100) < 1
    assert min(clocks) >= 1.0 and clocks == sorted(clocks)
    # Speed 1.0 is real time: the simulator never runs ahead of the wall clock (a loaded
    # machine can only slow it; its real-time factor is measured in bench/bench_simulator).
    received = max(r["wall"] for r in running if r["topic"] == "/clock")
    assert clocks[-1] - clocks[0] <= (received - started) + 0.01  # + one physics step
    # Stamps are step times (multiples of 10 ms of sim time), never beyond the clock.
    for r in records:
        if r["topic"] != "/clock":
            stamp = secs(r["msg"]["header"]["stamp"])
            assert stamp <= final_clock + 1e-9
            assert abs(stamp * 100 - round(stamp * 100)) < 1e-6
    assert min(scan_stamps) > 0


def test_scan_geometry_and_wall_range(ros, tmp_path):
    # The wall's face 2.0 m ahead of camera_depth_frame.
    start_simulator(ros, wall_ahead(tmp_path, 2.0 + CAMERA_X))
    scan = ros.echo("/scan", count=1)[0]["msg"]
    r = ranges(scan)
    assert scan["header"]["frame_id"] == "camera_depth_frame"
    assert len(r) == 640
    assert math.isclose(scan["angle_min"], -scan["angle_max"], abs_tol=1e-6)
    assert math.isclose(scan["angle_max"] - scan["angle_min"], math.radians(58), abs_tol=1e-4)
    assert math.isclose(scan["angle_increment"] * 639, math.radians(58), abs_tol=1e-5)
    assert math.isclose(scan["range_min"], 0.45, abs_tol=1e-6)
    assert abs(r[319] - 2.0) < 0.01 and abs(r[320] - 2.0) < 0.01
    edge = 2.0 / math.cos(math.radians(29))
    assert abs(r[0] - edge) < 0.01 and abs(r[639] - edge) < 0.01


def test_scan_from_map_image_world_and_rep117_values(ros, tmp_path):
    # 8 x 4 m map at 0.05 m, origin (-4, -2): a wall column whose face is at x = 2.0;
    # the robot looks along +x from x = 0.087, so the face is 2.0 m from the camera.
    cols, rows = 160, 80
    image = [[254] * cols for _ in range(rows)]
    for row in image:
        for c in range(120, 124):  # x in [2.0, 2.2)
            row[c] = 0
    write_pgm(tmp_path / "wall.pgm", image)
    world = tmp_path / "map_world.yaml"
    world.write_text(
        "image: wall.pgm\nresolution: 0.05\norigin: [-4.0, -2.0, 0.0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\nstart: [0.087, 0.0, 0.0]\n"
    )
    start_simulator(ros, world)
    r = ranges(ros.echo("/scan", count=1)[0]["msg"])
    assert abs(r[320] - 2.0) < 0.01


def test_nothing_in_range_is_plus_inf_and_too_close_is_minus_inf(ros, tmp_path):
    # Wall 0.3 m from the camera (inside range_min), robot facing it.
    start_simulator(ros, wall_ahead(tmp_path, 0.3 + CAMERA_X, thickness=0.2), yaw=0.0)
    r = ranges(ros.echo("/scan", count=1)[0]["msg"])
    assert all(v == -math.inf for v in r[300:340])


def test_scan_sees_nothing_gives_plus_inf(ros, tmp_path):
    start_simulator(ros, wall_ahead(tmp_path, 3.0), yaw=math.pi)
    r = ranges(ros.echo("/scan", count=1)[0]["msg"])
    assert all(v == math.inf for v in r)


def test_static_chain_on_tf_for_rosbag(ros, tmp_path):
    start_simulator(ros, wall_ahead(tmp_path, 3.0))
    records = ros.probe(["/tf"], count=30).wait(30)
    pairs = {
        (t["header"]["frame_id"], t["child_frame_id"])
        for r in records
        for t in r["msg"]["transforms"]
    }
    for pair in [
        ("odom", "base_footprint"),
        ("base_footprint", "base_link"),
        ("base_link", "camera_rgb_frame"),
        ("camera_rgb_frame", "camera_depth_frame"),
    ]:
        assert pair in pairs, pairs
    for r in records:
        for t in r["msg"]["transforms"]:
            assert secs(t["header"]["stamp"]) > 0
            assert not t["header"]["frame_id"].startswith("/")


def test_cameras_depth_points_rgb(ros, tmp_path):
    start_simulator(
        ros, wall_ahead(tmp_path, 2.0 + CAMERA_X), camera_width=64, camera_height=48, camera_rate=5
    )
    topics = [
        "/camera/depth/image_raw",
        "/camera/depth/points",
        "/camera/rgb/image_raw",
        "/camera/depth/camera_info",
        "/camera/rgb/camera_info",
    ]
    records = ros.probe(topics, count=1).wait(60)
    by_topic = {r["topic"]: r["msg"] for r in records}
    depth = by_topic["/camera/depth/image_raw"]
    assert depth["encoding"] == "32FC1" and depth["width"] == 64 and depth["height"] == 48
    assert depth["header"]["frame_id"] == "camera_depth_optical_frame"
    values = struct.unpack("<%df" % (64 * 48), bytes(depth["data"]))
    assert abs(values[24 * 64 + 32] - 2.0) < 0.01  # depth along the optical axis
    assert math.isnan(values[32])  # top row looks over the 1 m wall: NaN (REP 118)
    cloud = by_topic["/camera/depth/points"]
    assert [f["name"] for f in cloud["fields"]] == ["x", "y", "z"]
    assert cloud["width"] * cloud["height"] == 64 * 48 and not cloud["is_dense"]
    rgb = by_topic["/camera/rgb/image_raw"]
    assert rgb["encoding"] == "rgb8" and len(rgb["data"]) == 64 * 48 * 3
    info = by_topic["/camera/depth/camera_info"]
    assert info["width"] == 64 and info["K"][0] > 0


def test_the_simulator_is_its_own_clock(ros, tmp_path):
    """Its ROS time (what stamps its log messages) is its sim time, set where it publishes
    /clock; it does not subscribe to its own /clock (under /use_sim_time roscpp would, and
    each of the 100 messages per sim second would cross two more of its threads)."""
    start_simulator(ros, wall_ahead(tmp_path, 3.0), speed=2.0, start_time=1000.0)
    _, subscribers, _ = ros.system_state()
    assert "/simulator" not in dict(subscribers).get("/clock", [])
    probe = ros.probe(["/rosout"], duration=300, timeout=300)

    def warnings():
        return [
            r["msg"]
            for r in probe.messages()
            if r["msg"]["name"] == "/simulator" and "cmd_vel_mux/input/teleop" in r["msg"]["msg"]
        ]

    publish_once(ros, "cmd_vel", linear=0.5)  # the node warns: plain cmd_vel is ignored
    ros.wait_for(lambda: warnings(), 60, "the simulator's warning on /rosout")
    stamp = secs(warnings()[0]["header"]["stamp"])
    probe.stop()
    assert 1000.0 < stamp <= sim_time(ros)  # sim time (the wall clock reads about 1.8e9 s)
