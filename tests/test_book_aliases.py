"""The book's package names run our packages: rospy_tutorials, turtlebot_teleop (the
simulator and gmapping aliases are exercised by tests/chapter9)."""

import os
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from roskit import launch_node_list

SRC = Path(__file__).resolve().parent.parent / "catkin_ws" / "src"
ALIASES = SRC / "book_aliases"


def test_rosrun_rospy_tutorials_talker_and_listener(ros):
    ros.start(["rosrun", "rospy_tutorials", "talker"], name="talker")
    listener = ros.start(["rosrun", "rospy_tutorials", "listener"], name="listener")
    ros.wait_for_topic("chatter")
    message = ros.echo("chatter", count=1)[0]["msg"]["data"]
    assert message.startswith("hello world")
    ros.wait_for(lambda: "hello world" in ros.output(listener), 20, "the listener to hear it")


def test_alias_launch_files_resolve_to_ours(ros):
    nodes = ros.run(["roslaunch", "--nodes", "turtlebot_teleop", "keyboard_teleop.launch"])
    assert nodes.stdout.split(), nodes.stdout
    files = ros.run(["roslaunch", "--files", "turtlebot_gazebo", "turtlebot_playground.launch"])
    assert "bullet_turtlebot/launch/simulator.launch" in files.stdout


ALIAS_LAUNCHES = {
    "turtlebot_gazebo/launch/turtlebot_playground.launch": "bullet_turtlebot",
    "turtlebot_stage/launch/turtlebot_in_stage.launch": "bullet_turtlebot",
    "turtlebot_teleop/launch/keyboard_teleop.launch": "teleop_bot",
    "rospy_tutorials/launch/talker_listener.launch": "basics",
    "turtlebot_navigation/launch/amcl_demo.launch": "rosbook_demo",
}


@pytest.mark.parametrize("alias", sorted(ALIAS_LAUNCHES))
def test_alias_launch_file_includes_ours_with_the_same_arguments(alias):
    # Real files, not links (a relative link dangles in the install space); each includes
    # our launch file with pass_all_args and declares its arguments with the same defaults,
    # so `roslaunch --ros-args` lists them and the defaults cannot drift apart.
    package = ALIAS_LAUNCHES[alias]
    alias_path = ALIASES / alias
    ours_path = SRC / package / "launch" / alias_path.name
    assert not alias_path.is_symlink()
    alias_root, ours_root = ET.parse(alias_path).getroot(), ET.parse(ours_path).getroot()
    (include,) = alias_root.findall("include")
    assert include.get("file") == f"$(find {package})/launch/{alias_path.name}"
    assert include.get("pass_all_args") == "true"
    assert [(a.get("name"), a.get("default")) for a in alias_root.findall("arg")] == [
        (a.get("name"), a.get("default")) for a in ours_root.findall("arg")
    ]


@pytest.mark.parametrize(
    "package, launch_file, needs",
    [
        ("turtlebot_gazebo", "turtlebot_playground.launch", []),
        ("turtlebot_stage", "turtlebot_in_stage.launch", []),
        ("rosbook_demo", "mapping_live.launch", []),
        ("rosbook_demo", "drive_and_record.launch", ["bag:=drive.bag"]),
        ("explorer", "explore_sim.launch", []),
        ("wanderbot", "wander.launch", []),
    ],
)
def test_simulator_launch_opens_rviz_only_where_there_is_a_display(package, launch_file, needs):
    def nodes(display, *args):  # what `roslaunch --nodes` prints
        env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
        if display:
            env["DISPLAY"] = display
        return set(launch_node_list([package, launch_file, *needs, *args], env))

    assert "/rviz" in nodes(":99")
    assert "/rviz" not in nodes(":99", "gui:=false")
    headless = nodes(None)
    assert "/rviz" not in headless and "/simulator" in headless
