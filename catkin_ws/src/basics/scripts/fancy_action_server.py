#!/usr/bin/python3
"""fancy_action_server: the `timer` action with feedback, preemption and abort (chapter 5).

Node timer_action_server. Publishes feedback once a second; a cancel request preempts the
goal ("Timer preempted"); a goal over 60 s is aborted at once ("Timer aborted due to
too-long wait"), and so is a negative one. Time is ROS time (follows /clock under sim time).
"""

import time

import actionlib
import rospy
from basics import timer
from basics.msg import TimerAction, TimerFeedback, TimerResult
from rosbook_env.master_watch import survive_master_restart

POLL = 0.01  # seconds between preemption checks while waiting for the next feedback


def main():
    rospy.init_node("timer_action_server")
    survive_master_restart()  # re-registers with a restarted roscore

    def result_of(elapsed, updates):
        result = TimerResult()
        result.time_elapsed = rospy.Duration.from_sec(elapsed)
        result.updates_sent = updates
        return result

    def publish_feedback(elapsed, remaining):
        feedback = TimerFeedback()
        feedback.time_elapsed = rospy.Duration.from_sec(elapsed)
        feedback.time_remaining = rospy.Duration.from_sec(remaining)
        server.publish_feedback(feedback)

    def sleep(seconds):
        # Short naps: the timer loop checks for a cancel request between them.
        rospy.sleep(min(POLL, seconds))

    def do_timer(goal):
        start_time = rospy.get_time()
        wait = goal.time_to_wait.to_sec()
        problem = timer.goal_problem(wait)
        if problem:
            rospy.logwarn("goal of %f s refused: %s", wait, problem)
            server.set_aborted(result_of(rospy.get_time() - start_time, 0), problem)
            return
        try:
            outcome, elapsed, updates = timer.run_timer(
                wait, rospy.get_time, sleep, server.is_preempt_requested, publish_feedback
            )
        except rospy.ROSInterruptException:
            return  # shutting down
        # The book builds the success result inside the loop; it belongs after it.
        if outcome == "preempted":
            server.set_preempted(result_of(elapsed, updates), timer.PREEMPTED)
        else:
            server.set_succeeded(result_of(elapsed, updates), timer.SUCCEEDED)

    # Under sim time, take goals only once /clock has come: a goal must not be timed from 0.
    while rospy.get_rostime().is_zero() and not rospy.is_shutdown():
        time.sleep(0.01)
    server = actionlib.SimpleActionServer("timer", TimerAction, do_timer, False)
    server.start()
    rospy.spin()


if __name__ == "__main__":
    main()
