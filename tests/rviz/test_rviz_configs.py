"""The shipped rviz configs say what the book's steps set up by hand (fixed frames, display
types and topics), and view_rviz.launch / view_robot.launch resolve to them. The
navigation view's topics are the ones chapter 10's nodes publish and subscribe, with the
message types its displays and tools need."""

import subprocess
import sys
from pathlib import Path

import pytest
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent))

import rviz_checks as rc  # noqa: E402
from roskit import free_port, ros_environment  # noqa: E402

# view: (fixed frame, view controller, {display class: topic or None})
# (several displays of one class: a tuple of topics)
BOOK = {
    "teleop": (
        "camera_depth_frame",
        "rviz/Orbit",
        {
            "rviz/RobotModel": None,
            "rviz/PointCloud2": "/camera/depth/points",
            "rviz/LaserScan": "/scan",
            "rviz/Image": "/camera/rgb/image_raw",
        },
    ),
    "top_down": (
        "odom",
        "rviz/TopDownOrtho",
        {
            "rviz/RobotModel": None,
            "rviz/LaserScan": "/scan",
            "rviz/Odometry": "/odom",
            "rviz/TF": None,
        },
    ),
    "mapping": (
        "map",
        "rviz/TopDownOrtho",
        {
            "rviz/Map": "/map",
            "rviz/RobotModel": None,
            "rviz/LaserScan": "/scan",
            "rviz/TF": None,
        },
    ),
    "navigation": (
        "map",
        "rviz/TopDownOrtho",
        {
            "rviz/Map": (
                "/map",
                "/move_base/global_costmap/costmap",
                "/move_base/local_costmap/costmap",
            ),
            "rviz/Path": "/move_base/plan",
            "rviz/PoseArray": "/particlecloud",
            "rviz/RobotModel": None,
            "rviz/LaserScan": "/scan",
            "rviz/TF": None,
        },
    ),
    "robot": ("base_footprint", "rviz/Orbit", {"rviz/RobotModel": None, "rviz/TF": None}),
}
# Chapter 10's tools: rviz's 2D Pose Estimate and 2D Nav Goal, on the topics amcl and
# move_base subscribe (the book's Stage and Turtlebot views have both).
NAV_TOOLS = {
    "rviz/SetInitialPose": "/initialpose",
    "rviz/SetGoal": "/move_base_simple/goal",
}


def displays(config):
    manager = config["Visualization Manager"]
    found = {}
    for display in manager["Displays"]:
        if display.get("Enabled", True):
            topic = display.get("Topic") or display.get("Image Topic")
            found.setdefault(display["Class"], set()).add(topic)
    return manager["Global Options"]["Fixed Frame"], manager["Views"]["Current"]["Class"], found


@pytest.mark.parametrize("view", sorted(BOOK))
def test_config_sets_up_what_the_book_does(view):
    config = yaml.safe_load((rc.RVIZ / f"{view}.rviz").read_text())
    fixed, controller, found = displays(config)
    want_fixed, want_controller, want_displays = BOOK[view]
    assert fixed == want_fixed
    assert controller == want_controller
    for cls, topic in want_displays.items():
        assert cls in found, f"{view}.rviz lacks an enabled {cls}"
        for want in (topic,) if isinstance(topic, str) else topic or ():
            assert want in found[cls], f"{view}.rviz: no {cls} on {want}"
    robot = [d for d in config["Visualization Manager"]["Displays"] if d["Class"].endswith("Model")]
    assert all(d["Robot Description"] == "robot_description" for d in robot)


def tools(config):
    return {t["Class"]: t.get("Topic") for t in config["Visualization Manager"]["Tools"]}


@pytest.mark.parametrize("view", ["mapping", "navigation"])
def test_map_views_have_the_2d_pose_estimate_and_nav_goal_tools(view):
    found = tools(yaml.safe_load((rc.RVIZ / f"{view}.rviz").read_text()))
    for cls, topic in NAV_TOOLS.items():
        assert found.get(cls) == topic, f"{view}.rviz: {cls} on {found.get(cls)}, want {topic}"


@pytest.mark.parametrize(
    "launch, config",
    [(f"view_rviz.launch view:={view}", f"{view}.rviz") for view in sorted(BOOK)]
    + [("view_robot.launch", "robot.rviz")],
)
def test_view_launch_files_open_the_shipped_configs(launch, config):
    assert rviz_config_of("bullet_turtlebot", *launch.split()) == (rc.RVIZ / config).resolve()


@pytest.mark.parametrize(
    "launch, config",
    [
        # Chapter 10 as the book runs it: the navigation view (the stage with nav:=false is
        # chapter 9's simulator alone, with the teleop view).
        ("turtlebot_navigation amcl_demo.launch", "navigation.rviz"),
        ("turtlebot_stage turtlebot_in_stage.launch", "navigation.rviz"),
        ("turtlebot_stage turtlebot_in_stage.launch nav:=false", "teleop.rviz"),
    ],
)
def test_chapter_10_launch_files_open_the_navigation_view(launch, config):
    package, *args = launch.split()
    assert rviz_config_of(package, *args, "rviz:=true") == (rc.RVIZ / config).resolve()


def rviz_config_of(package, *launch):
    """The -d argument of the launch file's rviz node. `roslaunch --args` only resolves the
    launch file: no master needed."""
    done = subprocess.run(
        ["roslaunch", "--args", "rviz", package, *launch],
        env=ros_environment(free_port()),
        capture_output=True,
        text=True,
        timeout=120,  # a deadline only: roslaunch took 21 s to start at load 16
    )
    assert done.returncode == 0, done.stderr
    args = done.stdout.split()
    return Path(args[args.index("-d") + 1]).resolve()


# The message type each of navigation.rviz's displays and tools needs on its topic.
MESSAGE_TYPES = {
    "rviz/Map": "nav_msgs/OccupancyGrid",
    "rviz/Path": "nav_msgs/Path",
    "rviz/PoseArray": "geometry_msgs/PoseArray",
    "rviz/LaserScan": "sensor_msgs/LaserScan",
    "rviz/SetInitialPose": "geometry_msgs/PoseWithCovarianceStamped",
    "rviz/SetGoal": "geometry_msgs/PoseStamped",
}


@pytest.mark.timeout(180)
def test_navigation_view_topics_are_what_amcl_demo_publishes_and_subscribes(ros):
    # The book's chapter 10 command, without the window: every display's topic has a
    # publisher and every tool's topic a subscriber, of the type the display or tool needs.
    ros.start(["roslaunch", "turtlebot_navigation", "amcl_demo.launch", "rviz:=false"])
    manager = yaml.safe_load((rc.RVIZ / "navigation.rviz").read_text())["Visualization Manager"]
    shown = {
        (d["Topic"], MESSAGE_TYPES[d["Class"]])
        for d in manager["Displays"]
        if d.get("Enabled", True) and d.get("Topic")
    }
    used = {(t["Topic"], MESSAGE_TYPES[t["Class"]]) for t in manager["Tools"] if t.get("Topic")}
    assert len(shown) == 6 and len(used) == 2, (shown, used)

    def missing():
        publishers, subscribers, _ = ros.system_state()
        code, message, types = ros.master().getTopicTypes("/roskit")
        assert code == 1, message
        types = dict(types)
        published = {(name, types.get(name)) for name, _ in publishers}
        subscribed = {(name, types.get(name)) for name, _ in subscribers}
        return shown - published, used - subscribed

    # move_base advertises its topics before its make_plan service, amcl at start-up.
    ros.wait_for_service("move_base/make_plan", timeout=120)
    try:
        ros.wait_for(lambda: missing() == (set(), set()), 60, "the view's topics")
    except AssertionError:
        pass  # say which below
    unpublished, unsubscribed = missing()
    assert not unpublished, f"navigation.rviz shows topics nothing publishes: {unpublished}"
    assert not unsubscribed, f"navigation.rviz's tools send to no subscriber: {unsubscribed}"
