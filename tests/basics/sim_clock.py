#!/usr/bin/python3
"""Test helper (not a test): publishes /clock from --start seconds, --speed times wall time."""

import argparse
import time

import rospy
from rosgraph_msgs.msg import Clock


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--start", type=float, default=1000.0)
    parser.add_argument("--speed", type=float, default=10.0)
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("sim_clock", disable_signals=True)
    pub = rospy.Publisher("/clock", Clock, queue_size=10)
    wall_start = time.monotonic()
    while True:
        now = args.start + args.speed * (time.monotonic() - wall_start)
        pub.publish(Clock(clock=rospy.Time.from_sec(now)))
        time.sleep(0.01)


if __name__ == "__main__":
    try:
        main()
    except KeyboardInterrupt:
        pass
