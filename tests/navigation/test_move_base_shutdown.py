"""move_base_lite stopped (Ctrl-C) while it drives to a goal: one line says the goal ends with
the node, with no traceback from actionlib's execute thread and no warning that the goal was
left without a terminal status. (Whether the ABORTED status still reaches a client depends on
how far rospy's shutdown has gone.) No simulator: a map, fixed transforms and a goal across
the map keep a goal active."""

import signal
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
OFFICE = REPO / "maps" / "office.yaml"


def test_ctrl_c_mid_goal_aborts_it_in_one_line(ros):
    ros.start(["rosrun", "map_server", "map_server", str(OFFICE)], name="map_server")
    # The robot at the office's start (-8.5, 0), facing along the corridor.
    for x, parent, child in (("-8.5", "map", "odom"), ("0", "odom", "base_footprint")):
        tf = ["rosrun", "tf2_ros", "static_transform_publisher", x, "0", "0", "0", "0", "0"]
        ros.start(tf + [parent, child], name=f"tf_{child}")
    move_base = ros.start(["roslaunch", "move_base_lite", "move_base.launch"], name="move_base")
    ros.wait_for_topic("/move_base/status", timeout=90)
    status = ros.probe(["/move_base/status"], timeout=300)
    goal = "{header: {frame_id: map}, pose: {position: {x: 5.0, y: 0.0}, orientation: {w: 1.0}}}"
    # Latched for as long as it runs (`-1` latches for 3 s only): move_base gets the goal
    # however long its subscription takes to connect.
    ros.start(["rostopic", "pub", "/move_base_simple/goal", "geometry_msgs/PoseStamped", goal])

    def statuses():
        return [s["status"] for m in status.messages() for s in m["msg"]["status_list"]]

    ros.wait_for(lambda: 1 in statuses(), 90, "the goal to become ACTIVE")
    ros.stop(move_base, sig=signal.SIGINT, timeout=30)
    out = ros.output(move_base)
    assert "Traceback" not in out and "Exception in your execute callback" not in out, out
    assert "move_base: shutting down; the current goal is aborted" in out, out
    assert "did not set the goal to a terminal status" not in out, out
