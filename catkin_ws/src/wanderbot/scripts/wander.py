#!/usr/bin/python3
"""Wander: drive until an obstacle is within 0.8 m (or 30 s pass), then spin for 5 s.

Subscribes `scan` (sensor_msgs/LaserScan), publishes `cmd_vel` (geometry_msgs/Twist) at 10 Hz.
Private parameters: ~forward_speed (0.4 m/s), ~turn_speed (1.0 rad/s), ~min_range (0.8 m),
~drive_time (30 s), ~spin_time (5 s).
"""

import sys
import threading

import rospy
from geometry_msgs.msg import Twist
from rosbook_env.master_watch import survive_master_restart
from rosbook_env.params import ParamError, finite, positive
from rosbook_env.sim_time import warn_if_no_clock
from sensor_msgs.msg import LaserScan
from wanderbot.behaviours import Wanderer
from wanderbot.ranges import min_range


class WanderNode:
    def __init__(self):
        self.forward_speed = finite("~forward_speed", rospy.get_param("~forward_speed", 0.4))
        self.turn_speed = finite("~turn_speed", rospy.get_param("~turn_speed", 1.0))
        self.min_range = positive("~min_range", rospy.get_param("~min_range", 0.8))
        self.drive_time = positive("~drive_time", rospy.get_param("~drive_time", 30.0))
        self.spin_time = positive("~spin_time", rospy.get_param("~spin_time", 5.0))
        self.lock = threading.Lock()
        self.range_ahead = None
        self.got_scan = False
        self.cmd_vel_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        rospy.Subscriber("scan", LaserScan, self.scan_callback, queue_size=1)

    def scan_callback(self, msg):
        closest = min_range(msg.ranges, msg.range_min, msg.range_max)
        with self.lock:
            self.range_ahead = closest
            self.got_scan = True

    def run(self):
        rate = rospy.Rate(10, reset=True)  # reset: survive sim time jumping back
        while not rospy.is_shutdown() and (rospy.get_rostime().is_zero() or not self.got_scan):
            rospy.sleep(0.05)  # wait for /clock (sim time) and a first look ahead
        wanderer = Wanderer(rospy.get_time(), self.min_range, self.drive_time, self.spin_time)
        rospy.on_shutdown(lambda: self.cmd_vel_pub.publish(Twist()))
        state = None
        while not rospy.is_shutdown():
            with self.lock:
                range_ahead = self.range_ahead
            if wanderer.update(rospy.get_time(), range_ahead) != state:
                state = wanderer.state
                rospy.logdebug("wander: %s (range ahead %s)", state, range_ahead)
            twist = Twist()
            twist.linear.x, twist.angular.z = wanderer.command(self.forward_speed, self.turn_speed)
            self.cmd_vel_pub.publish(twist)
            rate.sleep()


def main():
    rospy.init_node("wander")
    survive_master_restart()  # re-registers with a restarted roscore
    warn_if_no_clock()  # says so if /use_sim_time waits for a /clock that never comes
    try:
        node = WanderNode()
    except ParamError as error:
        rospy.logfatal(str(error))
        return 2
    try:
        node.run()
    except rospy.ROSInterruptException:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
