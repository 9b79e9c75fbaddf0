"""Chapter 10 on any world: amcl's initial pose defaults to where the simulator puts the
robot, the world file's start pose (it was the maze's start on every world). Checked in the
parameters roslaunch sets (cheap, several worlds and launch files) and live on the office
world: amcl's first estimate is where the robot truly is."""

import math
from pathlib import Path

import pytest
import yaml

REPO = Path(__file__).resolve().parents[2]
WORLDS = REPO / "catkin_ws/src/bullet_turtlebot/worlds"


def world_start(world):
    return yaml.safe_load((WORLDS / f"{world}.yaml").read_text())["start"]


def amcl_initial_pose(ros, *launch):
    done = ros.run(["roslaunch", "--dump-params", *launch], timeout=180)
    params = yaml.safe_load(done.stdout)
    return [params[f"/amcl/initial_pose_{k}"] for k in "xya"]


@pytest.mark.parametrize(
    "launch",
    [
        ("turtlebot_navigation", "amcl_demo.launch", "world:=lab"),
        ("rosbook_demo", "amcl_demo.launch", "world:=office"),
        ("turtlebot_stage", "turtlebot_in_stage.launch", "world:=warehouse"),
    ],
)
def test_amcl_starts_at_the_worlds_start_pose(ros, launch):
    world = launch[-1].split(":=")[1]
    assert amcl_initial_pose(ros, *launch) == pytest.approx(world_start(world))


def test_a_world_given_as_a_path_and_an_explicit_pose(ros):
    path = WORLDS / "hospital.yaml"
    assert amcl_initial_pose(
        ros, "rosbook_demo", "amcl_demo.launch", f"world:={path}", f"map_file:={path}"
    ) == pytest.approx(world_start("hospital"))
    # x, y, yaw place the robot and amcl with it; initial_pose_* alone is amcl's.
    pose = amcl_initial_pose(
        ros, "rosbook_demo", "amcl_demo.launch", "world:=office", "x:=1.5", "y:=-2", "yaw:=0.5"
    )
    assert pose == pytest.approx([1.5, -2.0, 0.5])
    pose = amcl_initial_pose(
        ros, "turtlebot_navigation", "amcl_demo.launch", "world:=office", "initial_pose_x:=0.0"
    )
    assert pose == pytest.approx([0.0, *world_start("office")[1:]])


@pytest.mark.timeout(240)
def test_amcl_is_where_the_robot_is_on_the_office_world(ros):
    ros.start(
        [
            "roslaunch",
            "turtlebot_navigation",
            "amcl_demo.launch",
            "world:=office",
            "rviz:=false",
            "speed:=2",
        ],
        name="amcl_demo",
    )
    ros.wait_for_topic("amcl_pose", timeout=150)
    amcl = ros.echo("/amcl_pose", count=1, timeout=120)[0]["msg"]["pose"]["pose"]["position"]
    truth = ros.echo("/base_pose_ground_truth", count=1, timeout=60)[0]["msg"]["pose"]["pose"]
    error = math.hypot(amcl["x"] - truth["position"]["x"], amcl["y"] - truth["position"]["y"])
    print(f"office: amcl at ({amcl['x']:.3f}, {amcl['y']:.3f}), error {error:.3f} m")
    # The robot stands at the start: amcl's estimate is its initial pose, within the
    # initial cloud's spread (amcl's 0.5 m initial sigma; with the maze's start it was 9 m off).
    assert error < 0.3, (amcl, truth["position"])
