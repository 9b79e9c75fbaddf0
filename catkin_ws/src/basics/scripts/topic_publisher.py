#!/usr/bin/python3
"""topic_publisher: consecutive integers on `counter` at 2 Hz (Example 3-1)."""

import rospy
from rosbook_env.master_watch import survive_master_restart
from std_msgs.msg import Int32


def main():
    rospy.init_node("topic_publisher")
    survive_master_restart()  # re-registers with a restarted roscore
    pub = rospy.Publisher("counter", Int32, queue_size=10)
    rate = rospy.Rate(2, reset=True)  # reset: survive sim time jumping back
    count = 0
    while not rospy.is_shutdown():
        pub.publish(count)
        count += 1
        rate.sleep()


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
