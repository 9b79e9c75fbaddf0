#!/usr/bin/python3
"""simple_action_client: sends one `timer` goal and prints the time elapsed (chapter 5).

rosrun basics simple_action_client.py            # the book's 5 s goal
rosrun basics simple_action_client.py --duration 2
"""

import argparse
import sys

import rospy
from basics.action_client import SimpleActionClient
from basics.msg import TimerAction, TimerGoal
from basics.timer import seconds_arg


def main():
    parser = argparse.ArgumentParser(description="Sends a goal to the timer action server.")
    parser.add_argument(
        "--duration", type=seconds_arg, default=5.0, help="seconds to wait (default 5)"
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
    client.send_goal(goal)
    if not client.wait_for_result():
        return 1
    result = client.get_result()
    if result is None:
        print(f"No result: {client.get_goal_status_text()}", file=sys.stderr)
        return 1
    print("Time elapsed: %f" % result.time_elapsed.to_sec(), flush=True)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except rospy.ROSInterruptException:
        sys.exit(1)
