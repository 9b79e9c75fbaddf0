"""A roscore that outlives a simulator launch (issue 12): the simulator puts /use_sim_time back
as it was before the launch when the launch ends, and the book's rate-loop nodes say what to
do when /use_sim_time is on but no /clock comes."""

import pytest
from roskit import DEBIAN_PYTHON

# /clock from 10 s, advancing 0.01 s every 10 wall ms (the helper needs the wall clock).
CLOCK = """
import time
import rospy
from rosgraph_msgs.msg import Clock
rospy.init_node("test_clock", disable_signals=True)
pub = rospy.Publisher("/clock", Clock, queue_size=10)
tick = 0
while True:
    pub.publish(Clock(clock=rospy.Time.from_sec(10.0 + 0.01 * tick)))
    tick += 1
    time.sleep(0.01)
"""
FIX = "rosparam set use_sim_time false"


def use_sim_time(ros):
    done = ros.run(["rosparam", "get", "/use_sim_time"], check=False)
    return done.stdout.strip() if done.returncode == 0 else "unset"


@pytest.mark.parametrize("before", ["unset", "false", "true"])
def test_simulator_launch_puts_use_sim_time_back_when_it_ends(ros, before):
    if before != "unset":
        ros.run(["rosparam", "set", "/use_sim_time", before])
    launch = ros.start(["roslaunch", "bullet_turtlebot", "simulator.launch", "speed:=5"])
    ros.wait_for_topic("/clock", timeout=60)
    assert use_sim_time(ros) == "true"
    recorded = ros.run(["rosparam", "get", "/simulator/use_sim_time_before_launch"])
    assert recorded.stdout.strip().strip("'") == before
    ros.stop(launch, timeout=30)  # Ctrl+C
    assert launch.returncode is not None
    assert use_sim_time(ros) == before, ros.output(launch)
    if before == "unset":
        # Chapter 8 after the simulator's launch ended: the rate loop runs on the wall clock.
        ros.start(["rosrun", "teleop_bot", "keys_to_twist_using_rate.py"])
        ros.wait_for_topic("cmd_vel")
        assert len(ros.echo("cmd_vel", count=3)) == 3


RATE_LOOP_NODES = [
    ("teleop_bot", "keys_to_twist_using_rate.py", True),
    ("teleop_bot", "keys_to_twist_parameterized.py", True),
    ("teleop_bot", "keys_to_twist_with_ramps.py", True),
    ("wanderbot", "red_light_green_light.py", True),
    ("wanderbot", "wander.py", False),  # it waits for /scan as well
]


@pytest.mark.parametrize("package,script,publishes", RATE_LOOP_NODES)
def test_rate_loop_node_warns_on_sim_time_without_clock(ros, package, script, publishes):
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    node = ros.start(["rosrun", package, script])
    ros.wait_for(lambda: FIX in ros.output(node), 60, "the no-/clock warning")
    assert "[WARN]" in ros.output(node)
    if not publishes:
        return
    ros.start([DEBIAN_PYTHON, "-c", CLOCK], name="clock")
    ros.wait_for(lambda: "/clock has arrived" in ros.output(node), 60, "the node to see /clock")
    ros.wait_for_topic("cmd_vel")
    messages = ros.echo("cmd_vel", count=3)
    # The probe stamps a message with its own ROS time, 0 until its first /clock arrives.
    assert len(messages) == 3, messages
    assert all(m["ros"] == 0.0 or m["ros"] >= 10.0 for m in messages), messages
    assert node.poll() is None
