#!/usr/bin/python3
"""Turn each key on `keys` (w/x/a/d/s) into one Twist on `cmd_vel` (1 m/s, 1 rad/s)."""

import rospy
from geometry_msgs.msg import Twist
from rosbook_env.master_watch import survive_master_restart
from std_msgs.msg import String
from teleop_bot.keys import velocities_for_key


def keys_cb(msg, twist_pub):
    vels = velocities_for_key(msg.data)
    if vels is None:
        return  # unknown key
    t = Twist()
    t.linear.x, t.angular.z = vels
    twist_pub.publish(t)


def main():
    rospy.init_node("keys_to_twist")
    survive_master_restart()  # re-registers with a restarted roscore
    twist_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
    rospy.Subscriber("keys", String, keys_cb, twist_pub)
    rospy.spin()


if __name__ == "__main__":
    main()
