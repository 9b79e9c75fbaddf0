#!/usr/bin/python3
"""keys_to_twist at 20 Hz whose output ramps towards the key's target velocity.

./keys_to_twist_with_ramps.py _linear_scale:=0.5 _angular_scale:=1.0 \
    _linear_accel:=1.0 _angular_accel:=1.0
"""

import sys
import threading

import rospy
from geometry_msgs.msg import Twist
from rosbook_env.master_watch import survive_master_restart
from rosbook_env.params import ParamError, finite, positive
from rosbook_env.sim_time import warn_if_no_clock
from std_msgs.msg import String
from teleop_bot.keys import velocities_for_key
from teleop_bot.ramps import ramped_twist


def fetch_param(name, default, check):
    if rospy.has_param(name):
        return check(name, rospy.get_param(name))
    rospy.logwarn("parameter [%s] not defined. Defaulting to %.3f" % (name, default))
    return default


class RampedKeysToTwist:
    def __init__(self, scales, accels):
        self.linear_scale, self.angular_scale = scales
        self.linear_accel, self.angular_accel = accels
        self.lock = threading.Lock()
        self.target = (0.0, 0.0)  # (linear x, angular z)
        self.last = (0.0, 0.0)
        self.twist_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        rospy.Subscriber("keys", String, self.keys_cb)

    def keys_cb(self, msg):
        vels = velocities_for_key(msg.data, self.linear_scale, self.angular_scale)
        if vels is None:
            return  # unknown key
        with self.lock:
            self.target = vels

    def send_twist(self, dt):
        with self.lock:
            self.last = ramped_twist(
                self.last, self.target, dt, self.linear_accel, self.angular_accel
            )
            twist = Twist()
            twist.linear.x, twist.angular.z = self.last
        self.twist_pub.publish(twist)

    def spin(self, hz=20):
        # Only the timed loop publishes, so every step is limited by accel * (loop period).
        rate = rospy.Rate(hz, reset=True)  # reset: survive sim time jumping back
        while not rospy.is_shutdown() and rospy.get_rostime().is_zero():
            rospy.sleep(0.01)  # sim time: wait for /clock, or the first dt spans the epoch
        last_time = rospy.get_time()
        while not rospy.is_shutdown():
            now = rospy.get_time()
            self.send_twist(now - last_time)
            last_time = now
            rate.sleep()


def main():
    rospy.init_node("keys_to_twist")
    survive_master_restart()  # re-registers with a restarted roscore
    warn_if_no_clock()  # says so if /use_sim_time waits for a /clock that never comes
    try:
        angular_scale = fetch_param("~angular_scale", 0.1, finite)
        linear_scale = fetch_param("~linear_scale", 0.1, finite)
        angular_accel = fetch_param("~angular_accel", 1.0, positive)
        linear_accel = fetch_param("~linear_accel", 1.0, positive)
    except ParamError as error:
        rospy.logfatal(str(error))
        return 2
    node = RampedKeysToTwist((linear_scale, angular_scale), (linear_accel, angular_accel))
    try:
        node.spin()
    except rospy.ROSInterruptException:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
