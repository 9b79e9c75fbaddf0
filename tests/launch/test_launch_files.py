"""Every launch file a user can run (each package's launch/) starts and
brings up every node it declares: each node registers with the master and roslaunch keeps
running. The table must name every launch file, so a new one cannot go untested."""

import os
import pty
import sys
import xmlrpc.client
from pathlib import Path
from urllib.parse import urlparse

import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tests"))
sys.path.insert(0, str(REPO / "tests" / "tools"))
from listening import tcp_listening_ports, udp_ports  # noqa: E402
from roskit import launch_node_list  # noqa: E402

# launch file (relative to the repository) -> (arguments, needs a display, reads keys from a
# terminal: then it gets a pseudo-terminal as stdin)
# {tmp} in an argument is replaced by the test's folder.
LAUNCHES = {
    "catkin_ws/src/rosbook_demo/launch/drive_and_record.launch": (
        ["bag:={tmp}/drive record.bag", "speed:=2"],
        False,
        False,
    ),
    "catkin_ws/src/rosbook_demo/launch/mapping_from_bag.launch": (
        ["bag:={tmp}/tiny.bag", "rate:=0.2"],
        False,
        False,
    ),
    "catkin_ws/src/rosbook_demo/launch/mapping_live.launch": (
        ["rviz:=false", "speed:=2", "bag:={tmp}/live.bag"],
        False,
        False,
    ),
    "catkin_ws/src/rosbook_demo/launch/serve_map.launch": (
        ["rviz:=false", "map:={repo}/maps/office.yaml"],
        False,
        False,
    ),
    "catkin_ws/src/rosbook_demo/launch/amcl_demo.launch": (
        ["rviz:=false", "speed:=2"],
        False,
        False,
    ),
    "catkin_ws/src/rosbook_demo/launch/navigate_live.launch": (
        ["world:=office", "map_file:={repo}/maps/office.yaml", "speed:=2", "bag:={tmp}/nav.bag"],
        False,
        False,
    ),
    "catkin_ws/src/rosbook_demo/launch/navigation.launch": (
        ["map_file:={repo}/maps/office.yaml"],
        False,
        False,
    ),
    "catkin_ws/src/amcl_lite/launch/amcl.launch": ([], False, False),
    "catkin_ws/src/move_base_lite/launch/move_base.launch": ([], False, False),
    "catkin_ws/src/book_aliases/turtlebot_navigation/launch/amcl_demo.launch": (
        ["rviz:=false", "speed:=2"],
        False,
        False,
    ),
    "catkin_ws/src/basics/launch/talker_listener.launch": ([], False, False),
    "catkin_ws/src/book_aliases/rospy_tutorials/launch/talker_listener.launch": ([], False, False),
    "catkin_ws/src/book_aliases/turtlebot_gazebo/launch/turtlebot_playground.launch": (
        ["speed:=2"],
        False,
        False,
    ),
    "catkin_ws/src/book_aliases/turtlebot_stage/launch/turtlebot_in_stage.launch": (
        ["rviz:=false", "speed:=2"],
        False,
        False,
    ),
    "catkin_ws/src/book_aliases/turtlebot_teleop/launch/keyboard_teleop.launch": ([], False, True),
    "catkin_ws/src/bullet_turtlebot/launch/simulator.launch": (["speed:=2"], False, False),
    "catkin_ws/src/bullet_turtlebot/launch/turtlebot_in_stage.launch": (
        ["rviz:=true", "speed:=2"],
        True,
        False,
    ),
    "catkin_ws/src/bullet_turtlebot/launch/turtlebot_playground.launch": (
        ["speed:=2"],
        False,
        False,
    ),
    "catkin_ws/src/bullet_turtlebot/launch/view_robot.launch": ([], True, False),
    "catkin_ws/src/bullet_turtlebot/launch/view_rviz.launch": (["view:=top_down"], True, False),
    "catkin_ws/src/explorer/launch/explore.launch": ([], False, False),
    "catkin_ws/src/explorer/launch/explore_sim.launch": (["speed:=2"], False, False),
    "catkin_ws/src/gmapping_lite/launch/gmapping_turtlebot.launch": ([], False, False),
    "catkin_ws/src/teleop_bot/launch/keyboard_teleop.launch": ([], False, True),
    "catkin_ws/src/teleop_bot/launch/keys_to_twist_parameterized.launch": ([], False, False),
    "catkin_ws/src/teleop_bot/launch/keys_to_twist_with_ramps.launch": ([], False, False),
    "catkin_ws/src/teleop_bot/launch/teleop.launch": ([], False, True),
    "catkin_ws/src/wanderbot/launch/wander.launch": (["speed:=2"], False, False),
}


def all_launch_files():
    found = list((REPO / "catkin_ws" / "src").glob("**/launch/*.launch"))
    return sorted(str(p.relative_to(REPO)) for p in found)


def test_the_table_names_every_launch_file():
    assert all_launch_files() == sorted(LAUNCHES), "add new launch files to LAUNCHES"


def registered_nodes(uri):
    code, message, state = xmlrpc.client.ServerProxy(uri).getSystemState("/launch_test")
    assert code == 1, message
    return {node for group in state for _, nodes in group for node in nodes}


def write_tiny_bag(path):
    """Two seconds of a 10 Hz scan and its tf chain: enough for rosbag play to play."""
    import rosbag
    import rospy
    from geometry_msgs.msg import TransformStamped
    from sensor_msgs.msg import LaserScan
    from tf2_msgs.msg import TFMessage

    with rosbag.Bag(str(path), "w") as bag:
        for i in range(20):
            stamp = rospy.Time(1.0 + 0.1 * i)
            tf = TransformStamped()
            tf.header.stamp, tf.header.frame_id, tf.child_frame_id = stamp, "odom", "base_footprint"
            tf.transform.rotation.w = 1.0
            laser = TransformStamped()
            laser.header.stamp, laser.header.frame_id = stamp, "base_footprint"
            laser.child_frame_id = "camera_depth_frame"
            laser.transform.rotation.w = 1.0
            bag.write("/tf", TFMessage([tf, laser]), stamp)
            scan = LaserScan()
            scan.header.stamp, scan.header.frame_id = stamp, "camera_depth_frame"
            scan.angle_min, scan.angle_max, scan.angle_increment = -0.5, 0.5, 0.01
            scan.range_min, scan.range_max = 0.45, 8.0
            scan.ranges = [2.0] * 101
            bag.write("/scan", scan, stamp)


@pytest.mark.parametrize("launch_file", sorted(LAUNCHES))
def test_launch_file_brings_up_its_nodes(ros, tmp_path, request, launch_file):
    args, display, reads_stdin = LAUNCHES[launch_file]
    args = [a.replace("{tmp}", str(tmp_path)).replace("{repo}", str(REPO)) for a in args]
    if "bag:={tmp}/tiny.bag".replace("{tmp}", str(tmp_path)) in args:
        write_tiny_bag(tmp_path / "tiny.bag")
    path = str(REPO / launch_file)
    listed = launch_node_list([path, *args], ros.env)
    assert listed, f"roslaunch --nodes lists nothing for {launch_file}"
    expected = {"/" + name.lstrip("/") for name in listed}
    cmd = ["roslaunch", path, *args]
    if display:
        cmd = ["xvfb-run", "-a", "-s", "-screen 0 1280x800x24", *cmd]
    terminal = None
    if reads_stdin:
        keyboard, terminal = pty.openpty()
        request.addfinalizer(lambda: (os.close(keyboard), os.close(terminal)))
    # xvfb-run makes its auth folder in TMPDIR: the test's own, which pytest prunes.
    env = dict(ros.env, TMPDIR=str(tmp_path)) if display else None
    launch = ros.start(cmd, name=Path(launch_file).stem, stdin=terminal, env=env)
    uri = ros.env["ROS_MASTER_URI"]

    def all_up():
        assert launch.poll() is None, f"roslaunch exited:\n{ros.output(launch)[-4000:]}"
        return expected <= registered_nodes(uri)

    ros.wait_for(all_up, timeout=120, what=f"{sorted(expected)} to register", interval=0.5)
    assert "has died" not in ros.output(launch), ros.output(launch)[-4000:]
    for node in sorted(expected):
        assert_only_ros_ports(uri, node)


def assert_only_ros_ports(master_uri, node):
    """The node listens on ROS's own ports only: its XML-RPC server (the URI it registered)
    and its TCPROS server (where it offers /rosout, as every node publishes it), and binds at
    most one UDP port (roscpp's UDPROS socket, opened by every C++ node). The README's
    "Ports" section says so."""
    caller = "/launch_test"
    code, message, node_uri = xmlrpc.client.ServerProxy(master_uri).lookupNode(caller, node)
    assert code == 1, message
    api = xmlrpc.client.ServerProxy(node_uri)
    code, message, pid = api.getPid(caller)
    assert code == 1, message
    code, message, protocol = api.requestTopic(caller, "/rosout", [["TCPROS"]])
    assert code == 1 and protocol[0] == "TCPROS", (node, message)
    ros_ports = {urlparse(node_uri).port, protocol[2]}
    assert tcp_listening_ports(pid) <= ros_ports, (node, tcp_listening_ports(pid), ros_ports)
    assert len(udp_ports(pid)) <= 1, (node, udp_ports(pid))
