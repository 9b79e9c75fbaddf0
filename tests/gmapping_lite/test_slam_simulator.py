"""slam_gmapping live on the simulator (office world, drifting odometry): the book's
chapter 9 set-up end to end. The robot drives a short corridor route; the SLAM pose
(map -> odom composed with odometry) must end near the true pose."""

import math
import sys
from pathlib import Path

from rosbook_env.geometry import yaw_of
from rosbook_eval.poses import compose, inverse

sys.path.insert(0, str(Path(__file__).resolve().parent))
from slam_node_kit import load_turtlebot_tuning  # noqa: E402


def latest(transforms, parent, child):
    found = [
        t
        for m in transforms
        for t in m["msg"]["transforms"]
        if t["header"]["frame_id"] == parent and t["child_frame_id"] == child
    ]
    assert found, f"no {parent} -> {child} transform"
    t = found[-1]["transform"]
    return (t["translation"]["x"], t["translation"]["y"], yaw_of(t["rotation"]))


def test_live_mapping_in_the_office_tracks_the_true_pose(ros):
    ros.start(
        ["roslaunch", "bullet_turtlebot", "simulator.launch", "world:=office", "speed:=2"],
        name="simulator",
    )
    ros.wait_for_topic("scan", timeout=60)
    # The Turtlebot tuning with the main job's particle count and map interval.
    load_turtlebot_tuning(ros)
    for name, value in {"particles": 30, "map_update_interval": 2.0}.items():
        ros.run(["rosparam", "set", f"/slam_gmapping/{name}", str(value)])
    slam = ros.start(["rosrun", "gmapping_lite", "slam_gmapping"], name="slam_gmapping")
    ros.wait_for_topic("map", timeout=60)
    start = ros.echo("base_pose_ground_truth")[0]["msg"]["pose"]["pose"]
    driver = ros.start(
        ["rosrun", "gmapping_lite", "waypoint_driver", "--route", "corridor"], name="driver"
    )
    driver.wait(timeout=300)
    assert driver.returncode == 0, ros.output(driver)
    # Let the robot stop and the last scans be processed.
    tf = ros.probe(["/tf"], duration=4, timeout=30)
    transforms = tf.wait(40)
    truth = ros.echo("base_pose_ground_truth")[0]["msg"]["pose"]["pose"]
    map_to_odom = latest(transforms, "map", "odom")
    odom_to_base = latest(transforms, "odom", "base_footprint")
    slam_pose = compose(map_to_odom, odom_to_base)
    # The map frame starts at the robot's start pose (odometry's origin): compare there.
    s0 = (start["position"]["x"], start["position"]["y"], yaw_of(start["orientation"]))
    true_pose = (truth["position"]["x"], truth["position"]["y"], yaw_of(truth["orientation"]))
    true_rel = compose(inverse(s0), true_pose)
    error = math.hypot(slam_pose[0] - true_rel[0], slam_pose[1] - true_rel[1])
    assert error < 0.15, (slam_pose, true_rel)
    grid = ros.echo("map")[0]["msg"]
    assert grid["header"]["frame_id"] == "map"
    assert 100 in grid["data"] and 0 in grid["data"]
    log = ros.output(slam)
    assert "slam_gmapping: update 5 " in log
