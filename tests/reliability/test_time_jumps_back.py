"""Sim time jumping back (a simulator restarted, `rosbag play --loop`): the book's timed
nodes keep running and keep their timing on the new clock, rather than exiting (rospy.Rate
raises ROSTimeMovedBackwardsException unless it is told to reset) or waiting for the old
clock's deadline. Each row: a node, the topic it publishes, what must follow the jump, and
the inputs the node needs to publish at all."""

from pathlib import Path

import pytest
from roskit import DEBIAN_PYTHON

TOOLS = Path(__file__).resolve().parent.parent / "tools"
FAKE_SCAN = Path(__file__).resolve().parent.parent / "wanderbot" / "fake_scan.py"
START, JUMP_TO = 500.0, 1.0

ROWS = {
    "topic_publisher": (["rosrun", "basics", "topic_publisher.py"], "counter", None, []),
    "keys_to_twist_using_rate": (
        ["rosrun", "teleop_bot", "keys_to_twist_using_rate.py"],
        "cmd_vel",
        None,
        [],
    ),
    "keys_to_twist_with_ramps": (
        ["rosrun", "teleop_bot", "keys_to_twist_with_ramps.py"],
        "cmd_vel",
        None,
        [],
    ),
    # Its 3 s phases are timed on the new clock: it drives and stops again after the jump.
    "red_light_green_light": (
        ["rosrun", "wanderbot", "red_light_green_light.py"],
        "cmd_vel",
        {0.0, 0.5},
        [],
    ),
    # wander drives only once it has seen a scan.
    "wander": (
        ["rosrun", "wanderbot", "wander.py"],
        "cmd_vel",
        None,
        [[DEBIAN_PYTHON, str(FAKE_SCAN), "far@0"]],
    ),
}


@pytest.fixture(scope="module")
def sim_time_ros(shared_ros):
    shared_ros.run(["rosparam", "set", "/use_sim_time", "true"])
    return shared_ros


def linear_x(record):
    return record["msg"]["linear"]["x"]


@pytest.mark.parametrize("row", sorted(ROWS))
def test_node_keeps_running_when_sim_time_jumps_back(sim_time_ros, tmp_path, row):
    ros = sim_time_ros
    cmd, topic, speeds_after, inputs = ROWS[row]
    trigger = tmp_path / "jump"
    clock = ros.start(
        [DEBIAN_PYTHON, str(TOOLS / "jumping_clock.py"), f"--start={START}", f"--to={JUMP_TO}"]
        + [f"--trigger={trigger}"],
        name="clock",
    )
    extra = [ros.start(input_cmd) for input_cmd in inputs]
    node = ros.start(cmd, name=row)
    probe = None
    try:
        ros.wait_for_topic(topic)
        probe = ros.probe([topic], timeout=300)

        def received(since, until):
            """Messages the probe received while its clock was in [since, until)."""
            return [m for m in probe.messages() if since <= m["ros"] < until]

        def after():  # on the new clock (a probe's time is 0 before its first /clock)
            return received(JUMP_TO, START)

        before = lambda: received(START, float("inf"))  # noqa: E731
        ros.wait_for(lambda: len(before()) >= 3, 60, f"{topic} before the jump")
        trigger.touch()

        if speeds_after:
            ros.wait_for(
                lambda: {linear_x(m) for m in after()} >= speeds_after,
                90,
                f"{row} to drive and stop on the new clock",
            )
        else:
            ros.wait_for(lambda: len(after()) >= 5, 60, f"{topic} after the jump")
        assert node.poll() is None, ros.output(node)
        assert "Traceback" not in ros.output(node), ros.output(node)
    finally:
        for proc in [node, clock, *extra] + ([probe.proc] if probe else []):
            ros.stop(proc)
