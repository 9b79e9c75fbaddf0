#!/usr/bin/python3
"""Test helper (not a test): publishes /clock and, at each tick of it, one Twist on
/cmd_vel: --count ticks of --period sim seconds from --start. It starts once /cmd_vel and
/clock have their subscribers (--subscribers of each) connected, so none misses a message.
Then it holds the last tick's time until stopped (its connections stay up for inspection)."""

import argparse
import sys
import time

import rospy
from geometry_msgs.msg import Twist
from rosgraph_msgs.msg import Clock


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--count", type=int, required=True)
    parser.add_argument("--period", type=float, default=0.1)
    parser.add_argument("--start", type=float, default=1000.0)
    parser.add_argument("--subscribers", type=int, default=1)
    parser.add_argument("--linear", type=float, default=0.5)
    parser.add_argument("--angular", type=float, default=-0.3)
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("tick_publisher")
    clock_pub = rospy.Publisher("/clock", Clock, queue_size=100)
    twist_pub = rospy.Publisher("/cmd_vel", Twist, queue_size=100)
    # (Under sim time this node subscribes to its own /clock too: one more connection.)
    clocks = args.subscribers + (1 if rospy.get_param("/use_sim_time", False) else 0)
    deadline = time.monotonic() + 60
    while twist_pub.get_num_connections() < args.subscribers or (
        clock_pub.get_num_connections() < clocks
    ):
        if time.monotonic() > deadline:
            print("tick_publisher: subscribers did not connect", file=sys.stderr)
            return 3
        time.sleep(0.02)
    twist = Twist()
    twist.linear.x, twist.angular.z = args.linear, args.angular
    for tick in range(args.count):
        clock = Clock(clock=rospy.Time.from_sec(args.start + tick * args.period))
        clock_pub.publish(clock)
        twist_pub.publish(twist)
        time.sleep(0.01)  # pacing only: every message reaches every subscriber anyway
    while not rospy.is_shutdown():
        clock_pub.publish(clock)
        time.sleep(0.1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
