"""The book's chapter 8 teleop view on the real simulator: `roslaunch bullet_turtlebot
simulator.launch world:=playground speed:=1`, then rviz with teleop.rviz (fixed frame
camera_depth_frame) under Xvfb.  The screenshot must show the Turtlebot model, the
Kinect's point cloud and fake laser, and both camera images."""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import rviz_checks as rc  # noqa: E402
from rviz_checks import rs  # noqa: E402


def shows_an_image(panel, minimum=5000):
    """An Image panel with a picture has many pixels that are neither black nor white
    (rviz's "No Image" placeholder is black bars around white with black text)."""
    grey = panel.astype(np.int16)
    spread = grey.max(axis=2) - grey.min(axis=2)
    tone = grey.mean(axis=2)
    mid = (tone > 20) & (tone < 235)
    return int(np.count_nonzero(mid | (spread > 30))) >= minimum


def test_teleop_view_on_the_simulated_playground(ros):
    ros.start(
        ["roslaunch", "bullet_turtlebot", "simulator.launch", "world:=playground", "speed:=1"],
        name="simulator",
    )
    ros.wait_for_topic("/camera/depth/points", timeout=90)
    with rs.RvizSession(rc.RVIZ / "teleop.rviz", ros.env, ros.workdir / "rviz") as rviz:

        def ready(img):
            counts = rc.measure(rviz, img)[2]
            panels = rviz.panels(img)
            return (
                counts["robot"] > 3000
                and counts["cloud"] > 20000
                and counts["scan"] > 200
                and len(panels) == 2
                and all(shows_an_image(p) for p in panels)
            )

        path, img = rviz.settle(ready, timeout=60)
        view, masks, counts = rc.measure(rviz, img)
        panels = rviz.panels(img)
    what = f"screenshot {path}; pixel counts {counts}"
    assert counts["robot"] > 3000, "robot model missing: " + what
    assert counts["cloud"] > 20000, "depth cloud missing: " + what
    assert counts["scan"] > 200, "laser scan missing: " + what
    assert len(panels) == 2 and all(shows_an_image(p) for p in panels), (
        "RGB and depth images should both show pictures: " + what
    )
    # Chase camera: the robot low in the middle, what the Kinect sees above (ahead of) it.
    width, height = view.shape[1], view.shape[0]
    robot_x, robot_y = rs.centroid(masks["robot"])
    cloud_y = rs.centroid(masks["cloud"])[1]
    scan_y = rs.centroid(masks["scan"])[1]
    assert abs(robot_x - width / 2) < 0.1 * width and robot_y > 0.6 * height, what
    assert cloud_y < robot_y and scan_y < robot_y, what


def test_top_down_view_follows_the_simulated_robot(ros):
    ros.start(
        ["roslaunch", "bullet_turtlebot", "simulator.launch", "world:=playground", "speed:=1"],
        name="simulator",
    )
    ros.wait_for_topic("/odom", timeout=90)
    rc.drive_teleop(ros, 0.3, 0.3)  # a circle of radius 1 m
    with rs.RvizSession(rc.RVIZ / "top_down.rviz", ros.env, ros.workdir / "rviz") as rviz:

        def ready(img):
            _, masks, counts = rc.measure(rviz, img)
            trail = max(rs.extent(masks["odom"]))
            return counts["robot"] > 300 and counts["scan"] > 100 and trail > 80

        path, img = rviz.settle(ready, timeout=60)
        view, masks, counts = rc.measure(rviz, img)
    what = f"screenshot {path}; pixel counts {counts}"
    assert counts["robot"] > 300, "robot model missing: " + what
    assert counts["scan"] > 100, "laser scan missing: " + what
    # The view follows base_footprint; the odometry arrows trail behind over > 0.8 m.
    cx, cy = rc.view_centre(view)
    robot_x, robot_y = rs.centroid(masks["robot"])
    assert abs(robot_x - cx) < 15 and abs(robot_y - cy) < 15, what
    assert max(rs.extent(masks["odom"])) > 80, "odometry trail too short: " + what
