#!/usr/bin/python3
"""Like keys_to_twist.py, but repeats the last command on `cmd_vel` at 10 Hz."""

import threading

import rospy
from geometry_msgs.msg import Twist
from rosbook_env.master_watch import survive_master_restart
from rosbook_env.sim_time import warn_if_no_clock
from std_msgs.msg import String
from teleop_bot.keys import velocities_for_key


class KeysToTwist:
    def __init__(self):
        self.lock = threading.Lock()
        self.last_twist = Twist()  # initializes to zero
        self.twist_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        rospy.Subscriber("keys", String, self.keys_cb)

    def keys_cb(self, msg):
        vels = velocities_for_key(msg.data)
        if vels is None:
            return  # unknown key
        with self.lock:
            self.last_twist = Twist()
            self.last_twist.linear.x, self.last_twist.angular.z = vels
            self.twist_pub.publish(self.last_twist)

    def spin(self, hz=10):
        rate = rospy.Rate(hz, reset=True)  # reset: survive sim time jumping back
        while not rospy.is_shutdown():
            with self.lock:
                self.twist_pub.publish(self.last_twist)
            rate.sleep()


def main():
    rospy.init_node("keys_to_twist")
    survive_master_restart()  # re-registers with a restarted roscore
    warn_if_no_clock()  # says so if /use_sim_time waits for a /clock that never comes
    KeysToTwist().spin()


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
