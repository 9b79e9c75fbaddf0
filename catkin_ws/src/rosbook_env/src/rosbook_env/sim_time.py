"""Say so when a node's ROS time never starts.

Under `/use_sim_time` rospy's time stands at 0 until a `/clock` message arrives, and
`rospy.Rate.sleep` and `rospy.sleep` wait until then. With no simulator or
`rosbag play --clock` running that is for ever, silently: a rate loop never publishes.
A roscore that outlived a launch which set `/use_sim_time` is the usual cause.

Nodes call `warn_if_no_clock()` once, after `rospy.init_node()`.
"""

import threading
import time

import rospy
import rospy.rostime

WAIT = 3.0  # wall seconds without /clock before the warning
MESSAGE = (
    "/use_sim_time is true but no /clock has arrived in %g s: ROS time stands at 0, so "
    "rospy.Rate and rospy.sleep wait for ever. Start the simulator (or `rosbag play --clock`); "
    "or, if none should run, `rosparam set use_sim_time false` (or restart roscore) and start "
    "this node again."
)


def warn_if_no_clock(wait=WAIT):
    """On sim time, watch (in a daemon thread, by the wall clock) for the first /clock: log
    a warning naming the fix if none has come after `wait` seconds, and a note when one
    finally does. Returns the thread, or None on wall-clock time (nothing to watch)."""
    if rospy.rostime.is_wallclock():
        return None
    thread = threading.Thread(target=_watch, args=(wait,), name="clock_check", daemon=True)
    thread.start()
    return thread


def _watch(wait, poll=0.1):
    deadline = time.monotonic() + wait
    while not _clock_started():
        if rospy.is_shutdown():
            return
        if deadline is not None and time.monotonic() >= deadline:
            rospy.logwarn(MESSAGE, wait)
            deadline = None
        time.sleep(poll)  # polling the wall clock: ROS time is what does not move
    if deadline is None:
        rospy.loginfo("/clock has arrived: running on sim time")


def _clock_started():
    return not rospy.get_rostime().is_zero()
