#!/usr/bin/python3
"""latched_publisher: publishes on the latched topic `latched`, then only waits (chapter 3).

A subscriber that connects later still gets the last message:
    rosrun basics latched_publisher.py
    rostopic echo latched          # prints the message although it went out earlier

Parameters: ~count (int, default 1) messages "latched message N of COUNT", 0.1 s apart.
"""

import rospy
from rosbook_env.master_watch import survive_master_restart
from std_msgs.msg import String


def main():
    rospy.init_node("latched_publisher")
    survive_master_restart()  # re-registers with a restarted roscore
    count = rospy.get_param("~count", 1)
    if isinstance(count, bool) or not isinstance(count, int) or count < 1:
        rospy.logfatal("~count must be a positive integer, got %r", count)
        raise SystemExit(2)
    # The book writes latched=True; rospy's keyword is latch.
    pub = rospy.Publisher("latched", String, latch=True, queue_size=1)
    for n in range(1, count + 1):
        pub.publish(f"latched message {n} of {count}")
        rospy.sleep(0.1)
    rospy.loginfo("published %d message(s); the last stays latched on %s", count, pub.resolved_name)
    rospy.spin()


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
