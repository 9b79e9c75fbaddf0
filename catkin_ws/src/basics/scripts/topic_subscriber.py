#!/usr/bin/python3
"""topic_subscriber: prints each integer that arrives on `counter` (Example 3-2)."""

import rospy
from rosbook_env.master_watch import survive_master_restart
from std_msgs.msg import Int32


def callback(msg):
    print(msg.data, flush=True)


def main():
    rospy.init_node("topic_subscriber")
    survive_master_restart()  # re-registers with a restarted roscore
    rospy.Subscriber("counter", Int32, callback)
    rospy.spin()


if __name__ == "__main__":
    main()
