"""Chapter 9 live: the simulator (playground, speed 1), `rosrun gmapping slam_gmapping`'s
stand-in (gmapping_lite) and mapping.rviz while the robot drives a small circle.  The
screenshot must show the map being built (free space and walls on unknown), the robot on
it near the map origin, and the laser scan lying on the map's walls: map → odom →
base_footprint → camera_depth_frame all line up on screen."""

import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import rviz_checks as rc  # noqa: E402
from rviz_checks import rs  # noqa: E402

PX_PER_M = 30.0  # mapping.rviz's TopDownOrtho scale
LINEAR, ANGULAR = 0.2, 0.4  # the teleop command: a circle of radius LINEAR / ANGULAR = 0.5 m
# m: the robot stays within the circle's diameter of its start (the map origin); on top of
# that, SLAM's error in so short a run and the drawn model's centroid against base_link.
NEAR_ORIGIN = 2 * LINEAR / ANGULAR + 0.25


def dilate(mask, radius):
    """Grow a boolean mask by `radius` pixels (square neighbourhood)."""
    grown = mask.copy()
    for dy in range(-radius, radius + 1):
        for dx in range(-radius, radius + 1):
            grown |= np.roll(np.roll(mask, dy, axis=0), dx, axis=1)
    return grown


def test_mapping_view_while_slam_builds_the_map(ros):
    ros.start(
        ["roslaunch", "bullet_turtlebot", "simulator.launch", "world:=playground", "speed:=1"],
        name="simulator",
    )
    ros.wait_for_topic("/scan", timeout=90)
    # A 30 m square map (the book sets the bounds too) updated every 2 s keeps the test short.
    slam = ["rosrun", "gmapping_lite", "slam_gmapping", "_map_update_interval:=2.0"]
    slam += [f"_{k}:={v}" for k, v in (("xmin", -15), ("ymin", -15), ("xmax", 15), ("ymax", 15))]
    ros.start(slam, name="slam_gmapping")
    rc.drive_teleop(ros, LINEAR, ANGULAR)
    # rviz starts while SLAM makes its first map; the Map display subscribes whenever.
    with rs.RvizSession(rc.RVIZ / "mapping.rviz", ros.env, ros.workdir / "rviz") as rviz:

        def ready(img):
            _, masks, counts = rc.measure(rviz, img)
            seen, on_walls = scan_on_walls(masks)
            mapped = counts["free"] > 20000 and counts["wall"] > 300
            return mapped and seen > 100 and on_walls > 0.5

        path, img = rviz.settle(ready, timeout=60)
        view, masks, counts = rc.measure(rviz, img)
    what = f"screenshot {path}; pixel counts {counts}"
    # The playground is several metres across: > 20 m² seen free, walls, unknown around.
    assert counts["free"] > 20000, "free space missing: " + what
    assert counts["wall"] > 300, "walls missing: " + what
    assert counts["unknown"] > counts["free"], "unknown should surround the map: " + what
    # The map frame starts at the robot's first pose; the circle keeps it near there.
    cx, cy = rc.view_centre(view)
    robot_x, robot_y = rs.centroid(masks["robot"])
    assert math.hypot(robot_x - cx, robot_y - cy) < NEAR_ORIGIN * PX_PER_M, what
    # Where the map is already known, the scan is drawn over the walls it hits.
    seen, on_walls = scan_on_walls(masks)
    assert seen > 100, "no scan over the mapped area: " + what
    assert on_walls > 0.5, f"only {on_walls:.0%} of the scan lies on walls: " + what


def scan_on_walls(masks):
    """Scan pixels over the mapped area, and the fraction of them within 0.1 m of a wall.

    The map is republished every few seconds, so the scan may also hit walls not mapped
    yet; those (over unknown cells) are left out.
    """
    known = dilate(masks["free"] | masks["wall"], 2)
    seen = masks["scan"] & known
    count = int(np.count_nonzero(seen))
    near_walls = np.count_nonzero(seen & dilate(masks["wall"], 3))
    return count, near_walls / max(count, 1)
