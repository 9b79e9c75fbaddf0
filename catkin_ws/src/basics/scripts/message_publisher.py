#!/usr/bin/python3
"""message_publisher: random basics/Complex numbers on `complex` at 2 Hz (Example 3-4)."""

from random import random

import rospy
from basics.msg import Complex
from rosbook_env.master_watch import survive_master_restart


def main():
    rospy.init_node("message_publisher")
    survive_master_restart()  # re-registers with a restarted roscore
    pub = rospy.Publisher("complex", Complex, queue_size=10)
    rate = rospy.Rate(2, reset=True)  # reset: survive sim time jumping back
    while not rospy.is_shutdown():
        msg = Complex()
        msg.real = random()
        msg.imaginary = random()
        pub.publish(msg)
        rate.sleep()


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
