#!/usr/bin/python3
"""fancy_action_client: a `timer` goal with feedback, preemption or abort (chapter 5).

The book's three runs, without editing the code:
    rosrun basics fancy_action_client.py                     # 5 s goal: SUCCEEDED (3)
    rosrun basics fancy_action_client.py --preempt-after 3   # cancel after 3 s: PREEMPTED (2)
    rosrun basics fancy_action_client.py --duration 500      # too long: ABORTED (4)
"""

import argparse
import sys
import threading
import time

import rospy
from basics import timer
from basics.action_client import SimpleActionClient
from basics.msg import TimerAction, TimerGoal

PRINTING = threading.Lock()


def print_block(lines):
    """Print `lines` as one block: feedback arrives on rospy's thread while the main thread
    prints the result, and print() writes a line and its newline separately."""
    with PRINTING:
        sys.stdout.write("".join(line + "\n" for line in lines))
        sys.stdout.flush()


def feedback_cb(feedback):
    print_block(
        timer.feedback_lines(feedback.time_elapsed.to_sec(), feedback.time_remaining.to_sec())
    )


def main():
    parser = argparse.ArgumentParser(description="Sends a goal to the fancy timer action server.")
    parser.add_argument(
        "--duration",
        type=timer.seconds_arg,
        default=5.0,
        help="seconds to wait (default 5; over 60 or negative: the server aborts)",
    )
    parser.add_argument(
        "--preempt-after",
        type=timer.delay_arg,
        metavar="SECONDS",
        help="cancel the goal if still running this many seconds after sending it (book: 3)",
    )
    args = parser.parse_args(rospy.myargv()[1:])

    rospy.init_node("timer_action_client")
    client = SimpleActionClient("timer", TimerAction)
    if not client.wait_for_server(rospy.Duration(1.0)):
        rospy.loginfo("waiting for the action server %s", rospy.resolve_name("timer"))
        if not client.wait_for_server():
            return 1  # shut down while waiting

    goal = TimerGoal()
    goal.time_to_wait = rospy.Duration.from_sec(args.duration)
    while rospy.get_rostime().is_zero() and not rospy.is_shutdown():
        time.sleep(0.01)  # sim time: wait for /clock, or the delay below counts from 0
    sent = rospy.get_rostime()
    client.send_goal(goal, feedback_cb=feedback_cb)
    if args.preempt_after is not None:
        # The book sleeps, then cancels; waiting for the result instead ends early when the
        # goal finishes first. The delay counts from sending the goal, however long sending
        # took (a zero timeout would mean "forever", hence the check).
        patience = rospy.Duration.from_sec(args.preempt_after) - (rospy.get_rostime() - sent)
        if patience <= rospy.Duration(0) or not client.wait_for_result(patience):
            client.cancel_goal()

    if not client.wait_for_result():
        return 1
    result = client.get_result()
    lines = timer.result_lines(
        client.get_state(),
        client.get_goal_status_text(),
        None if result is None else result.time_elapsed.to_sec(),
        None if result is None else result.updates_sent,
    )
    print_block(lines)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except rospy.ROSInterruptException:
        sys.exit(1)
