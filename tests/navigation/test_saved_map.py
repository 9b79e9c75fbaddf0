"""Chapter 10 on a map made by chapter 9's SLAM, as a reader runs it: `roslaunch
turtlebot_navigation amcl_demo.launch map_file:=.../maps/office_slam.yaml` on the office
world (headless), the robot's pose on that map given with initial_pose_x/y/a, and one goal
sent as rviz's 2D Nav Goal does (a PoseStamped in frame map on move_base_simple/goal). The
robot must arrive where the goal is in the world (the simulator's ground truth), and the
plan and amcl's particle cloud must have been published for rviz to show."""

import math
import os
from pathlib import Path

import numpy as np
import pytest
import yaml
from PIL import Image
from rosbook_env.geometry import yaw_of
from scipy import ndimage

REPO = Path(__file__).resolve().parents[2]
SLAM_MAP = REPO / "maps" / "office_slam.yaml"
WORLD_MAP = REPO / "catkin_ws/src/bullet_turtlebot/worlds/office.yaml"
# The office world's start (worlds/office.yaml): the SLAM run that made office_slam started
# there, so its map frame is this pose in the world (maps/README.md).
MAP_IN_WORLD = (-8.5, 0.0, 0.0)
# Map frame: 3 m straight along the corridor from where the map was begun, short enough
# to keep the test quick.
GOAL = (3.0, 0.0, 0.0)
SPEED = 4  # the simulator waits for move_base if it lags (wait_for_commands)
# move_base_lite stops when its own pose (amcl's map -> odom with odometry) is within
# xy_goal_tolerance of the goal (config/move_base_params.yaml). That is what the controller
# guarantees, and it is checked exactly, on the pose move_base's feedback reports.
XY_GOAL_TOLERANCE = 0.05
# Where the robot truly ends adds amcl's error. Along this corridor it is the larger part:
# the robot stopped 0.07-0.22 m short of the goal in the world, always along the corridor,
# and as far short on the world's own map (maps/office.yaml) as on this one, while
# move_base's own pose was within 0.05 m of the goal: the corridor's walls run along the
# Kinect's 58 degree view and its far end is beyond the 8 m range, so amcl's estimate
# drifts along it (0.08 m ahead of the robot after the first update standing still, 0.1-0.2
# m ahead after 3 m). Not the goal tolerance, the slow-down for the goal, the goal's
# inflation or the map's offset (its walls near the route are within 0.02 m of the
# world's, placed at the start pose). Chapter 10's 0.2 m / 0.2 rad (test_navigation.py)
# plus how far the map's walls are off the world's there (map_error_near) bounds it.
GOAL_POSITION_LIMIT = 0.2
GOAL_YAW_LIMIT = 0.2


def load_map(yaml_path):
    meta = yaml.safe_load(yaml_path.read_text())
    with Image.open(yaml_path.parent / meta["image"]) as image:
        return meta, np.asarray(image.convert("L"))


def map_error_near(centre, radius):
    """How far the SLAM map's walls within `radius` of `centre` (map frame) lie from the
    world's true walls: the 90th percentile, so that a few stray wall cells (which amcl's
    likelihood field outvotes) do not count."""
    meta, slam = load_map(SLAM_MAP)
    world_meta, world = load_map(WORLD_MAP)
    res, wres = meta["resolution"], world_meta["resolution"]
    occupied = slam < (1.0 - meta["occupied_thresh"]) * 255
    rows, cols = np.nonzero(occupied)
    x = meta["origin"][0] + (cols + 0.5) * res
    y = meta["origin"][1] + (slam.shape[0] - rows - 0.5) * res
    near = np.hypot(x - centre[0], y - centre[1]) < radius
    wx, wy = to_world(x[near], y[near])
    wall_free = world >= (1.0 - world_meta["occupied_thresh"]) * 255
    distance = ndimage.distance_transform_edt(wall_free) * wres
    c = ((wx - world_meta["origin"][0]) / wres).astype(int)
    r = world.shape[0] - 1 - ((wy - world_meta["origin"][1]) / wres).astype(int)
    c, r = np.clip(c, 0, world.shape[1] - 1), np.clip(r, 0, world.shape[0] - 1)
    return float(np.percentile(distance[r, c], 90))


def to_world(x, y):
    ox, oy, oa = MAP_IN_WORLD
    return (
        ox + np.cos(oa) * x - np.sin(oa) * y,
        oy + np.sin(oa) * x + np.cos(oa) * y,
    )


def angle_between(a, b):
    return abs(math.atan2(math.sin(a - b), math.cos(a - b)))


@pytest.mark.timeout(300)
def test_goal_on_a_slam_map_is_reached_in_the_world(ros):
    ros.start(
        [
            "roslaunch",
            "turtlebot_navigation",
            "amcl_demo.launch",
            "world:=office",
            f"map_file:={os.fspath(SLAM_MAP)}",
            # The simulator puts the robot at the world's start ...
            f"x:={MAP_IN_WORLD[0]}",
            f"y:={MAP_IN_WORLD[1]}",
            f"yaw:={MAP_IN_WORLD[2]}",
            # ... which is the SLAM map's origin: where the reader tells amcl it is.
            "initial_pose_x:=0.0",
            "initial_pose_y:=0.0",
            "initial_pose_a:=0.0",
            "rviz:=false",
            f"speed:={SPEED}",
            "wait_for_commands:=0.3",
            "seed:=1",
        ],
        name="amcl_demo",
    )
    ros.wait_for_service("move_base/make_plan", timeout=150)
    ros.wait_for_topic("/move_base/result", timeout=60)
    results = ros.probe(["/move_base/result"], count=1, timeout=240)
    feedback = ros.probe(["/move_base/feedback"], timeout=240)
    # rviz's 2D Nav Goal: one PoseStamped in the fixed frame, latched so that move_base
    # gets it however long its subscription takes to connect on a loaded machine.
    goal = (
        f"{{header: {{frame_id: map}}, pose: {{position: {{x: {GOAL[0]}, y: {GOAL[1]}}}, "
        f"orientation: {{z: {math.sin(GOAL[2] / 2)}, w: {math.cos(GOAL[2] / 2)}}}}}}}"
    )
    ros.start(
        ["rostopic", "pub", "/move_base_simple/goal", "geometry_msgs/PoseStamped", goal],
        name="nav_goal",
    )
    (result,) = results.wait(250)
    status = result["msg"]["status"]
    # The robot has stopped (move_base's last command is a stop): where it is now.
    truth = ros.echo("/base_pose_ground_truth", count=1, timeout=60)[0]["msg"]["pose"]["pose"]
    plan = ros.echo("/move_base/plan", count=1, timeout=60)[0]["msg"]
    cloud = ros.echo("/particlecloud", count=1, timeout=60)[0]["msg"]
    amcl = ros.echo("/amcl_pose", count=1, timeout=60)[0]["msg"]["pose"]["pose"]["position"]
    # move_base's own pose when it decided: its last feedback (sent every cycle before the
    # decision, as move_base's base_position). amcl may correct map -> odom again after the
    # stop, so a pose rebuilt later from tf is not the one move_base stopped on.
    feedback.stop()
    decided = feedback.messages()[-1]["msg"]["feedback"]["base_position"]["pose"]["position"]
    own = (decided["x"], decided["y"])

    goal_x, goal_y = to_world(GOAL[0], GOAL[1])
    goal_yaw = GOAL[2] + MAP_IN_WORLD[2]
    position_error = math.hypot(truth["position"]["x"] - goal_x, truth["position"]["y"] - goal_y)
    yaw_error = angle_between(yaw_of(truth["orientation"]), goal_yaw)
    route_centre = (GOAL[0] / 2, GOAL[1] / 2)
    map_error = map_error_near(route_centre, math.hypot(GOAL[0], GOAL[1]) / 2 + 0.5)
    amcl_x, amcl_y = to_world(amcl["x"], amcl["y"])
    print(
        f"office_slam goal {GOAL} (world ({goal_x:.2f}, {goal_y:.2f})): status "
        f"{status['status']} '{status['text']}', position error {position_error:.3f} m, yaw "
        f"error {yaw_error:.3f} rad; plan of {len(plan['poses'])} poses, particle cloud of "
        f"{len(cloud['poses'])}"
    )
    print(
        f"robot at ({truth['position']['x']:.3f}, {truth['position']['y']:.3f}), amcl's last "
        f"update in the world ({amcl_x:.3f}, {amcl_y:.3f}); the map's walls near the route "
        f"are off the world's by {map_error:.2f} m (90th percentile)"
    )
    own_error = math.hypot(own[0] - GOAL[0], own[1] - GOAL[1])
    print(
        f"move_base's own pose when it stopped ({own[0]:.3f}, {own[1]:.3f}): {own_error:.3f} m off"
    )
    assert status["status"] == 3, status  # SUCCEEDED
    assert own_error <= XY_GOAL_TOLERANCE, own
    assert position_error <= GOAL_POSITION_LIMIT + map_error, (position_error, map_error)
    assert yaw_error <= GOAL_YAW_LIMIT, yaw_error
    # What rviz's Path and PoseArray displays show, in the fixed frame map.
    assert plan["header"]["frame_id"] == "map" and plan["poses"], plan["header"]
    end = plan["poses"][-1]["pose"]["position"]
    assert math.hypot(end["x"] - GOAL[0], end["y"] - GOAL[1]) < 0.1, end
    assert cloud["header"]["frame_id"] == "map" and cloud["poses"], cloud["header"]
