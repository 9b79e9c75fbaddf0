#!/usr/bin/python3
"""A /clock that runs at real speed from --start sim seconds and, once the file --trigger
exists, jumps back to --to and runs on from there: a simulator restart or `rosbag play
--loop`, as the nodes under test see it. Ticks of 10 ms of sim time every 10 wall ms."""

import argparse
import os
import time

import rospy
from rosgraph_msgs.msg import Clock


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--start", type=float, required=True)
    parser.add_argument("--to", type=float, required=True)
    parser.add_argument("--trigger", required=True, help="jump back once this file exists")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("jumping_clock", disable_signals=True)
    pub = rospy.Publisher("/clock", Clock, queue_size=10)
    now, jumped = args.start, False
    while not rospy.is_shutdown():
        if not jumped and os.path.exists(args.trigger):
            now, jumped = args.to, True
            print(f"jumping_clock: jumped back to {now} s", flush=True)
        pub.publish(Clock(clock=rospy.Time.from_sec(now)))
        now += 0.01
        time.sleep(0.01)  # the clock's own pace (wall time), not a wait for a condition


if __name__ == "__main__":
    main()
