#!/usr/bin/python3
"""Test helper (not a test): publishes /clock from --start seconds, advancing --step simulated
seconds every 10 ms of wall time. Fixed steps, not wall time × speed: on a loaded machine the
simulation slows down instead of jumping ahead."""

import argparse
import time

import rospy
from rosgraph_msgs.msg import Clock


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--start", type=float, default=1000.0)
    parser.add_argument("--step", type=float, default=0.2)
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("sim_clock", disable_signals=True)
    pub = rospy.Publisher("/clock", Clock, queue_size=10)
    ticks = 0
    while True:
        pub.publish(Clock(clock=rospy.Time.from_sec(args.start + args.step * ticks)))
        ticks += 1
        time.sleep(0.01)


if __name__ == "__main__":
    try:
        main()
    except KeyboardInterrupt:
        pass
