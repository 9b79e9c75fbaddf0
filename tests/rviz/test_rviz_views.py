"""The shipped rviz views, rendered by real rviz under Xvfb against a real roscore,
robot_state_publisher with the Turtlebot URDF, and a fake sensor source (so these tests
do not need the simulator).  Each screenshot is checked for the colours and places the
book's chapter 8 and 9 views should show."""

import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import rviz_checks as rc  # noqa: E402
from rviz_checks import rs  # noqa: E402

SETTLE = 30  # s of screenshots at most before judging the last one


def describe(path, counts):
    return f"screenshot {path}; pixel counts {counts}"


def test_teleop_view_chase_camera_shows_robot_cloud_scan_and_images(ros):
    rc.start_fake_robot(ros, "--wall", "2.0")
    with rs.RvizSession(rc.RVIZ / "teleop.rviz", ros.env, ros.workdir / "rviz") as rviz:

        def ready(img):
            _, _, counts = rc.measure(rviz, img)
            sky = max(rs.count_rgb(p, rc.SKY, 4) for p in rviz.panels(img))
            return counts["robot"] > 3000 and counts["cloud"] > 20000 and sky > 1000

        path, img = rviz.settle(ready, timeout=SETTLE)
        view, masks, counts = rc.measure(rviz, img)
        panels = rviz.panels(img)
    what = describe(path, counts)
    assert counts["robot"] > 3000, "robot model (tan plates) missing: " + what
    assert counts["cloud"] > 20000, "depth cloud (green to blue) missing: " + what
    assert counts["scan"] > 500, "laser scan (magenta) missing: " + what

    # Chase camera: the robot sits low in the middle, the wall 2 m ahead above it,
    # and the scan's line lies across the wall at the camera's height.
    robot_x, robot_y = rs.centroid(masks["robot"])
    cloud_x, cloud_y = rs.centroid(masks["cloud"])
    scan_x, scan_y = rs.centroid(masks["scan"])
    width, height = view.shape[1], view.shape[0]
    assert abs(robot_x - width / 2) < 0.1 * width, what
    assert robot_y > 0.6 * height, what
    assert cloud_y < robot_y - 0.2 * height, what
    assert abs(cloud_x - robot_x) < 0.05 * width, what
    cloud_w, cloud_h = rs.extent(masks["cloud"])
    assert abs(scan_y - cloud_y) < cloud_h / 2, what
    assert rs.extent(masks["scan"])[0] > 0.8 * cloud_w, "scan spans the wall: " + what

    # The two Image panels: the colour camera and the 0..8 m depth image (2 m → grey 64).
    assert len(panels) == 2, f"expected the RGB and depth image panels; {path}"
    sky = [rs.count_rgb(p, rc.SKY, 4) for p in panels]
    floor = [rs.count_rgb(p, rc.FLOOR, 4) for p in panels]
    depth = [rs.count_rgb(p, rc.DEPTH_GREY, 3) for p in panels]
    rgb_panel = sky.index(max(sky))
    assert sky[rgb_panel] > 1000 and floor[rgb_panel] > 1000, f"RGB image not shown: {path}"
    assert depth[1 - rgb_panel] > 1000, f"depth image not shown as grey 64: {path}"
    assert not rs.is_blank(panels[rgb_panel])


def test_top_down_view_follows_robot_with_odometry_trail(ros):
    rc.start_fake_robot(ros, "--wall", "2.0", "--circle", "1.0")
    with rs.RvizSession(rc.RVIZ / "top_down.rviz", ros.env, ros.workdir / "rviz") as rviz:

        def ready(img):
            _, masks, counts = rc.measure(rviz, img)
            trail = max(rs.extent(masks["odom"]))
            return counts["robot"] > 300 and counts["scan"] > 300 and trail > 80

        path, img = rviz.settle(ready, timeout=SETTLE)
        view, masks, counts = rc.measure(rviz, img)
    what = describe(path, counts)
    assert counts["robot"] > 300, "robot model missing: " + what
    assert counts["scan"] > 300, "laser scan missing: " + what
    assert counts["odom"] > 100, "odometry arrows missing: " + what
    # 100 px/m, centred on base_footprint: the robot in the middle, the scan's wall
    # 2 m (200 px) away from it, and the odometry trail behind it over > 0.8 m.
    cx, cy = rc.view_centre(view)
    robot_x, robot_y = rs.centroid(masks["robot"])
    assert math.hypot(robot_x - cx, robot_y - cy) < 15, what
    scan_x, scan_y = rs.centroid(masks["scan"])
    assert abs(math.hypot(scan_x - cx, scan_y - cy) - 200) < 25, what
    assert max(rs.extent(masks["odom"])) > 80, "odometry trail too short: " + what


def test_mapping_view_shows_map_greys_in_proportion(ros):
    rc.start_fake_robot(ros, "--wall", "2.0", "--map")
    ros.wait_for_topic("/map")
    # fake_turtlebot's room: 8 m × 8 m of unknown, a 5 m square room, walls 0.15 m thick.
    px_per_m2 = 30.0**2
    expected = {
        "unknown": (64.0 - 25.0) * px_per_m2,
        "wall": (25.0 - 4.7**2) * px_per_m2,
        "free": 4.7**2 * px_per_m2,
    }
    with rs.RvizSession(rc.RVIZ / "mapping.rviz", ros.env, ros.workdir / "rviz") as rviz:

        def ready(img):
            counts = rc.measure(rviz, img)[2]
            return all(abs(counts[k] / v - 1) < 0.1 for k, v in expected.items()) and (
                counts["scan"] > 50
            )

        path, img = rviz.settle(ready, timeout=SETTLE)
        view, masks, counts = rc.measure(rviz, img)
    what = describe(path, counts)
    for name, want in expected.items():
        assert abs(counts[name] / want - 1) < 0.1, f"{name}: want ≈{want:.0f} px; " + what
    # Map origin (-4, -4): the room is centred on the map frame, which the view centres.
    cx, cy = rc.view_centre(view)
    free_x, free_y = rs.centroid(masks["free"])
    assert abs(free_x - cx) < 5 and abs(free_y - cy) < 5, what
    robot_x, robot_y = rs.centroid(masks["robot"])
    assert abs(robot_x - cx) < 6 and abs(robot_y - cy) < 6, what
    # REP 103 on screen: the robot faces +x, drawn to the right, so its scan of the wall
    # 2 m ahead is a vertical line 60 px right of the centre.
    scan_x, scan_y = rs.centroid(masks["scan"])
    assert abs(scan_x - (cx + 60)) < 6 and abs(scan_y - cy) < 6, what
    scan_w, scan_h = rs.extent(masks["scan"])
    assert scan_h > 5 * scan_w, "scan line should be vertical: " + what


def test_view_robot_launch_shows_the_model_and_its_frames(ros):
    launch = ["roslaunch", "bullet_turtlebot", "view_robot.launch"]
    with rs.RvizSession(env=ros.env, workdir=ros.workdir / "rviz", command=launch) as rviz:

        def ready(img):
            counts = rc.measure(rviz, img)[2]
            labels = rs.count_rgb(rviz.view(img), (255, 255, 255), 10)
            return counts["robot"] > 8000 and labels > 300

        path, img = rviz.settle(ready, timeout=SETTLE)
        view, masks, counts = rc.measure(rviz, img)
        nodes = ros.run(["rosnode", "list"]).stdout.split()
    what = describe(path, counts)
    assert "/robot_state_publisher" in nodes and "/rviz" in nodes, nodes
    # A close-up: the plates fill a good part of the view, frame names drawn in white.
    assert counts["robot"] > 8000, "robot model missing: " + what
    assert rs.count_rgb(view, (255, 255, 255), 10) > 300, "TF frame names missing: " + what
    robot_x, robot_y = rs.centroid(masks["robot"])
    assert abs(robot_x - view.shape[1] / 2) < 0.1 * view.shape[1], what
