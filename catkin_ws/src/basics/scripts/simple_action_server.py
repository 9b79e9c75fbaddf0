#!/usr/bin/python3
"""simple_action_server: the `timer` action, no feedback (chapter 5), node timer_action_server.

Waits for the goal's time_to_wait, then succeeds with time_elapsed and updates_sent=0.
A negative wait is aborted. Time is ROS time, so it follows /clock under use_sim_time.
"""

import time

import actionlib
import rospy
from basics.msg import TimerAction, TimerResult
from basics.timer import NEGATIVE
from rosbook_env.master_watch import survive_master_restart


def main():
    rospy.init_node("timer_action_server")
    survive_master_restart()  # re-registers with a restarted roscore

    def do_timer(goal):
        start_time = rospy.get_time()
        wait = goal.time_to_wait.to_sec()
        result = TimerResult()
        if wait < 0:
            server.set_aborted(result, f"{NEGATIVE} ({wait:f} s)")
            return
        try:
            rospy.sleep(wait)
        except rospy.ROSInterruptException:
            return  # shutting down
        result.time_elapsed = rospy.Duration.from_sec(rospy.get_time() - start_time)
        result.updates_sent = 0
        server.set_succeeded(result)

    # Under sim time, take goals only once /clock has come: a goal must not be timed from 0.
    while rospy.get_rostime().is_zero() and not rospy.is_shutdown():
        time.sleep(0.01)
    # auto_start=False: the book's advice, avoids a start-up race.
    server = actionlib.SimpleActionServer("timer", TimerAction, do_timer, False)
    server.start()
    rospy.spin()


if __name__ == "__main__":
    main()
