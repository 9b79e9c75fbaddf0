"""The shipped rviz configs say what the book's steps set up by hand (fixed frames, display
types and topics), and view_rviz.launch / view_robot.launch resolve to them."""

import subprocess
import sys
from pathlib import Path

import pytest
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent))

import rviz_checks as rc  # noqa: E402
from roskit import free_port, ros_environment  # noqa: E402

# view: (fixed frame, view controller, {display class: topic or None})
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
    "robot": ("base_footprint", "rviz/Orbit", {"rviz/RobotModel": None, "rviz/TF": None}),
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
        if topic is not None:
            assert topic in found[cls], f"{view}.rviz: {cls} not on {topic}"
    robot = [d for d in config["Visualization Manager"]["Displays"] if d["Class"].endswith("Model")]
    assert all(d["Robot Description"] == "robot_description" for d in robot)


@pytest.mark.parametrize(
    "launch, config",
    [(f"view_rviz.launch view:={view}", f"{view}.rviz") for view in sorted(BOOK)]
    + [("view_robot.launch", "robot.rviz")],
)
def test_view_launch_files_open_the_shipped_configs(launch, config):
    # `roslaunch --args` only resolves the launch file: no master needed.
    done = subprocess.run(
        ["roslaunch", "--args", "rviz", "bullet_turtlebot", *launch.split()],
        env=ros_environment(free_port()),
        capture_output=True,
        text=True,
        timeout=30,
    )
    assert done.returncode == 0, done.stderr
    args = done.stdout.split()
    assert Path(args[args.index("-d") + 1]).resolve() == (rc.RVIZ / config).resolve()
