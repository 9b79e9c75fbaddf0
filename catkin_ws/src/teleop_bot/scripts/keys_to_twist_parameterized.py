#!/usr/bin/python3
"""keys_to_twist at 10 Hz with speeds scaled by ~linear_scale and ~angular_scale.

./keys_to_twist_parameterized.py _linear_scale:=0.5 _angular_scale:=0.4
"""

import sys
import threading

import rospy
from geometry_msgs.msg import Twist
from rosbook_env.master_watch import survive_master_restart
from rosbook_env.params import ParamError, finite
from rosbook_env.sim_time import warn_if_no_clock
from std_msgs.msg import String
from teleop_bot.keys import velocities_for_key


def scale_param(name, label, default):
    if rospy.has_param(name):
        return finite(name, rospy.get_param(name))
    rospy.logwarn("WARNING: %s scale not provided. Defaulting to %.1f" % (label, default))
    return default


class KeysToTwist:
    def __init__(self, linear_scale, angular_scale):
        self.linear_scale = linear_scale
        self.angular_scale = angular_scale
        self.lock = threading.Lock()
        self.last_twist = Twist()  # initializes to zero
        self.twist_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        rospy.Subscriber("keys", String, self.keys_cb)

    def keys_cb(self, msg):
        vels = velocities_for_key(msg.data, self.linear_scale, self.angular_scale)
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
    try:
        linear_scale = scale_param("~linear_scale", "linear", 0.1)  # default to very slow
        angular_scale = scale_param("~angular_scale", "angular", 0.1)
    except ParamError as error:
        rospy.logfatal(str(error))
        return 2
    try:
        KeysToTwist(linear_scale, angular_scale).spin()
    except rospy.ROSInterruptException:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
