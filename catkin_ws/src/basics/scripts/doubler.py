#!/usr/bin/python3
"""doubler: republishes each Int32 from `number` times two on `doubled` (Example 3-6)."""

import rospy
from basics.doubling import double_int32
from rosbook_env.master_watch import survive_master_restart
from std_msgs.msg import Int32


def main():
    rospy.init_node("doubler")
    survive_master_restart()  # re-registers with a restarted roscore
    # Advertise before subscribing: the book's order lets the callback run before pub exists.
    pub = rospy.Publisher("doubled", Int32, queue_size=10)

    def callback(msg):
        doubled = double_int32(msg.data)
        if doubled is None:
            rospy.logwarn("2 x %d does not fit in an Int32; nothing published", msg.data)
            return
        pub.publish(Int32(doubled))

    rospy.Subscriber("number", Int32, callback)
    rospy.spin()


if __name__ == "__main__":
    main()
