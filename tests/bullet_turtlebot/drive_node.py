#!/usr/bin/python3
"""Publish geometry_msgs/Twist for a number of seconds of ROS (sim) time, then zero.

drive_node.py --topic T --linear V --angular W --seconds S [--rate HZ] [--no-stop]
drive_node.py --topic T --linear nan --count 3 --no-stop   (a few raw messages)
"""

import argparse
import time

import rospy
from geometry_msgs.msg import Twist


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--topic", required=True)
    parser.add_argument("--linear", type=float, default=0.0)
    parser.add_argument("--angular", type=float, default=0.0)
    parser.add_argument("--seconds", type=float, default=0.0)
    parser.add_argument("--rate", type=float, default=10.0)
    parser.add_argument("--count", type=int, default=0)
    parser.add_argument("--no-stop", action="store_true")
    args = parser.parse_args(rospy.myargv()[1:])

    rospy.init_node("drive", anonymous=True)
    pub = rospy.Publisher(args.topic, Twist, queue_size=10)
    deadline = time.monotonic() + 30.0  # wall time: sim time may run much faster
    while pub.get_num_connections() == 0 and not rospy.is_shutdown():
        if time.monotonic() > deadline:
            raise SystemExit(f"nobody subscribes to {args.topic}")
        time.sleep(0.01)
    while rospy.Time.now().to_sec() == 0 and not rospy.is_shutdown():
        time.sleep(0.01)
    twist = Twist()
    twist.linear.x = args.linear
    twist.angular.z = args.angular
    if args.count:
        for _ in range(args.count):
            pub.publish(twist)
            rospy.sleep(0.05)
    else:
        rate = rospy.Rate(args.rate)
        start = rospy.get_time()
        while not rospy.is_shutdown() and rospy.get_time() - start < args.seconds:
            pub.publish(twist)
            rate.sleep()
    if not args.no_stop:
        for _ in range(3):
            pub.publish(Twist())
            rospy.sleep(0.05)
    rospy.sleep(0.2)  # let the last messages leave


if __name__ == "__main__":
    main()
