"""The Turtlebot URDF: it parses with urdfdom's check_urdf, its Kobuki dimensions are the
contract's, and robot_state_publisher broadcasts exactly the frames the simulator and
the book's rviz steps use (REP 105 chain, Kinect optical frames)."""

import math
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import rviz_checks as rc  # noqa: E402

# child: (parent, xyz, quaternion xyzw) as robot_state_publisher must broadcast them
OPTICAL = (-0.5, 0.5, -0.5, 0.5)  # rpy (-pi/2, 0, -pi/2)
EXPECTED = {
    "base_link": ("base_footprint", (0, 0, 0.0102), (0, 0, 0, 1)),
    "camera_rgb_frame": ("base_link", (-0.087, -0.0125, 0.287), (0, 0, 0, 1)),
    "camera_depth_frame": ("camera_rgb_frame", (0, 0.025, 0), (0, 0, 0, 1)),
    "camera_depth_optical_frame": ("camera_depth_frame", (0, 0, 0), OPTICAL),
    "camera_rgb_optical_frame": ("camera_rgb_frame", (0, 0, 0), OPTICAL),
    "camera_link": ("camera_rgb_frame", None, (0, 0, 0, 1)),
    "wheel_left_link": ("base_link", (0, 0.115, 0.025), None),
    "wheel_right_link": ("base_link", (0, -0.115, 0.025), None),
    "caster_front_link": ("base_link", None, None),
    "caster_back_link": ("base_link", None, None),
    "plate_bottom_link": ("base_link", (-0.01364, 0, 0.1306), (0, 0, 0, 1)),
    "plate_middle_link": ("base_link", (-0.01364, 0, 0.1874), (0, 0, 0, 1)),
    "plate_top_link": ("base_link", (-0.01364, 0, 0.3966), (0, 0, 0, 1)),
}


def test_check_urdf_parses_the_model(ros):
    done = ros.run(["check_urdf", str(rc.URDF)])
    assert "Successfully Parsed XML" in done.stdout
    assert "root Link: base_footprint" in done.stdout


def test_kobuki_dimensions_match_the_contract():
    robot = ET.parse(rc.URDF).getroot()
    links = {link.get("name"): link for link in robot.findall("link")}
    body = links["base_link"].find("visual/geometry/cylinder")
    assert float(body.get("radius")) == 0.177
    for side in ("left", "right"):
        wheel = links[f"wheel_{side}_link"].find("visual/geometry/cylinder")
        assert float(wheel.get("radius")) * 2 == 0.070
    joints = {joint.get("name"): joint for joint in robot.findall("joint")}
    left_y = float(joints["wheel_left_joint"].find("origin").get("xyz").split()[1])
    right_y = float(joints["wheel_right_joint"].find("origin").get("xyz").split()[1])
    assert math.isclose(left_y - right_y, 0.230)
    # Wheels sit on the floor: base_link height + wheel centre height == wheel radius.
    wheel_z = float(joints["wheel_left_joint"].find("origin").get("xyz").split()[2])
    assert math.isclose(0.0102 + wheel_z, 0.035, abs_tol=0.001)
    # No meshes: Debian has no turtlebot_description to resolve package:// URIs.
    assert robot.find(".//mesh") is None
    # Every visual has a material with a colour, so rviz never draws default white.
    named = {m.get("name") for m in robot.findall("material") if m.find("color") is not None}
    for visual in robot.iter("visual"):
        assert visual.find("material").get("name") in named


def test_robot_state_publisher_broadcasts_the_frames(ros):
    ros.run(["rosparam", "set", "robot_description", "-t", str(rc.URDF)])
    ros.start(["rosrun", "robot_state_publisher", "robot_state_publisher"])
    ros.wait_for_topic("/tf_static")
    (message,) = ros.echo("/tf_static", count=1)
    got = {t["child_frame_id"]: t for t in message["msg"]["transforms"]}
    assert set(got) == set(EXPECTED), "exactly these frames, wheels included"
    for child, (parent, xyz, quat) in EXPECTED.items():
        tf = got[child]
        assert tf["header"]["frame_id"] == parent, child
        if xyz is not None:
            t = tf["transform"]["translation"]
            assert close((t["x"], t["y"], t["z"]), xyz), (child, t)
        if quat is not None:
            q = tf["transform"]["rotation"]
            got_q = (q["x"], q["y"], q["z"], q["w"])
            assert close(got_q, quat) or close(got_q, [-v for v in quat]), (child, got_q)


def close(values, wanted, tol=1e-6):
    return all(math.isclose(a, b, abs_tol=tol) for a, b in zip(values, wanted, strict=True))
