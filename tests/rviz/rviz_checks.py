"""What the rviz screenshot tests share: file locations, the colour key of the shipped
views, a fake robot, and the measurements made on a screenshot."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tools"))

import rviz_screenshot as rs  # noqa: E402

REPO = Path(__file__).resolve().parents[2]
PACKAGE = REPO / "catkin_ws" / "src" / "bullet_turtlebot"
URDF = PACKAGE / "urdf" / "turtlebot.urdf"
RVIZ = PACKAGE / "rviz"
FAKE = Path(__file__).resolve().parent / "fake_turtlebot.py"

# Colour key of the shipped views (see README.rviz.md).  Lit surfaces keep their hue
# and saturation while brightness changes with the light, so solids go by HSV.
ROBOT_PLATES = dict(hue=(15, 45), sat=(0.3, 0.9), val=(0.15, 1.0))  # tan plates
CLOUD = dict(hue=(100, 200), sat=(0.5, 1.0), val=(0.3, 1.0))  # green (near) to blue (far)
ODOM_ARROWS = dict(hue=(50, 70), sat=(0.6, 1.0), val=(0.3, 1.0))  # yellow
SCAN = (255, 0, 255)  # magenta flat squares, unlit
MAP_FREE = (255, 255, 255)
MAP_WALL = (0, 0, 0)
MAP_UNKNOWN = (112, 137, 134)
# What fake_turtlebot.py shows the camera; depth 2 m on the 0..8 m scale is grey 64.
SKY = (70, 130, 180)
FLOOR = (34, 139, 34)
DEPTH_GREY = (64, 64, 64)


def start_fake_robot(ros, *fake_args):
    """robot_description + robot_state_publisher + fake sensors, all real ROS nodes."""
    ros.run(["rosparam", "set", "robot_description", "-t", str(URDF)])
    ros.start(["rosrun", "robot_state_publisher", "robot_state_publisher"])
    ros.start(["/usr/bin/python3", str(FAKE), *fake_args], name="fake_turtlebot")
    ros.wait_for_topic("/scan")
    ros.wait_for_topic("/tf_static")


def drive_teleop(ros, linear, angular):
    """Drive the simulated robot with a constant command at 10 Hz through the book's teleop
    input of the command mux."""
    twist = f"{{linear: {{x: {linear}}}, angular: {{z: {angular}}}}}"
    ros.start(
        ["rostopic", "pub", "-r", "10", "/cmd_vel_mux/input/teleop", "geometry_msgs/Twist", twist],
        name="teleop",
    )


def measure(rviz, img):
    """Masks and counts of the colour key inside the 3D view."""
    view = rviz.view(img)
    hsv = rs.hsv(view)
    masks = {
        "robot": rs.mask_hsv(view, **ROBOT_PLATES, hsv_of_img=hsv),
        "cloud": rs.mask_hsv(view, **CLOUD, hsv_of_img=hsv),
        "odom": rs.mask_hsv(view, **ODOM_ARROWS, hsv_of_img=hsv),
        "scan": rs.mask_rgb(view, SCAN, tol=40),
        "free": rs.mask_rgb(view, MAP_FREE, tol=3),
        "wall": rs.mask_rgb(view, MAP_WALL, tol=3),
        "unknown": rs.mask_rgb(view, MAP_UNKNOWN, tol=3),
    }
    counts = {name: int(mask.sum()) for name, mask in masks.items()}
    return view, masks, counts


def view_centre(view):
    return view.shape[1] / 2.0, view.shape[0] / 2.0
