#!/usr/bin/python3
"""talker: publishes "hello world <time>" on `chatter` at 10 Hz (chapter 2).

Debian has no rospy_tutorials; this is the talker its launch file starts.
"""

import rospy
from rosbook_env.master_watch import survive_master_restart
from std_msgs.msg import String


def main():
    rospy.init_node("talker")
    survive_master_restart()  # re-registers with a restarted roscore
    pub = rospy.Publisher("chatter", String, queue_size=10)
    rate = rospy.Rate(10, reset=True)  # reset: survive sim time jumping back
    while not rospy.is_shutdown():
        hello = f"hello world {rospy.get_time()}"
        rospy.loginfo(hello)
        pub.publish(hello)
        rate.sleep()


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
