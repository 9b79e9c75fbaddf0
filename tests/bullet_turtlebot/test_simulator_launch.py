"""The book's launch commands and the book's `rosbag record -O data.bag /scan /tf`."""

import math

import rosbag
from simkit import drive, last_pose, ranges, wait_sim_seconds


def launch(ros, name, *args):
    proc = ros.start(["roslaunch", "bullet_turtlebot", name, *args], name=name)
    ros.wait_for_topic("/scan", timeout=60)
    return proc


def test_turtlebot_in_stage_launch_brings_up_the_maze(ros):
    launch(ros, "turtlebot_in_stage.launch", "rviz:=false", "speed:=5", "nav:=false")
    assert ros.run(["rosparam", "get", "/use_sim_time"]).stdout.strip() == "true"
    assert "robot_description" in ros.run(["rosparam", "list"]).stdout
    static = ros.echo("/tf_static", count=1)[0]["msg"]["transforms"]
    children = {t["child_frame_id"] for t in static}
    assert {"base_link", "camera_rgb_frame", "camera_depth_frame"} <= children
    x, y, _, _ = last_pose(ros)
    assert (x, y) == (0.75, 0.75)  # the maze's start pose
    assert len(ranges(ros.echo("/scan", count=1)[0]["msg"])) == 640


def test_playground_launch_with_start_pose_args(ros):
    launch(ros, "turtlebot_playground.launch", "x:=1.0", "y:=-1.5", "yaw:=1.57", "speed:=5")
    x, y, yaw, _ = last_pose(ros)
    assert (x, y) == (1.0, -1.5) and abs(yaw - 1.57) < 1e-6


def test_rosbag_of_scan_and_tf_alone_holds_the_whole_chain(ros, tmp_path):
    launch(ros, "turtlebot_in_stage.launch", "rviz:=false", "speed:=2", "nav:=false")
    bag_path = tmp_path / "data.bag"
    rec = ros.start(["rosbag", "record", "-O", str(bag_path), "/scan", "/tf"], name="record")
    ros.wait_for(lambda: bag_path.with_suffix(".bag.active").exists(), 30, "rosbag to start")
    wait_sim_seconds(ros, 1.0)
    drive(ros, 0.2, 0.3, 3.0)
    ros.stop(rec)
    ros.wait_for(lambda: bag_path.exists(), 30, "the bag to be closed")
    pairs, scans, stamps = set(), 0, []
    with rosbag.Bag(str(bag_path)) as bag:
        for topic, msg, _ in bag.read_messages():
            if topic == "/scan":
                scans += 1
                stamps.append(msg.header.stamp.to_sec())
                assert msg.header.frame_id == "camera_depth_frame"
            else:
                for t in msg.transforms:
                    pairs.add((t.header.frame_id, t.child_frame_id))
                    stamps.append(t.header.stamp.to_sec())
    assert scans > 10
    assert min(stamps) > 0
    chain = [
        ("odom", "base_footprint"),
        ("base_footprint", "base_link"),
        ("base_link", "camera_rgb_frame"),
        ("camera_rgb_frame", "camera_depth_frame"),
    ]
    for pair in chain:
        assert pair in pairs, (pair, pairs)
    assert all(math.isfinite(s) for s in stamps)
