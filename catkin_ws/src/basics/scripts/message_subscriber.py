#!/usr/bin/python3
"""message_subscriber: prints each basics/Complex from `complex` (Example 3-5)."""

import rospy
from basics.msg import Complex
from rosbook_env.master_watch import survive_master_restart


def callback(msg):
    print("Real:", msg.real)
    print("Imaginary:", msg.imaginary)
    print(flush=True)


def main():
    rospy.init_node("message_subscriber")
    survive_master_restart()  # re-registers with a restarted roscore
    rospy.Subscriber("complex", Complex, callback)
    rospy.spin()


if __name__ == "__main__":
    main()
