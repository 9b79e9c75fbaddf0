#!/usr/bin/python3
"""Keep the newest /clock in a file, for tests that wait on sim time: one long-lived
subscriber instead of a new probe process (a Python start-up, most of a CPU second) for every
look at the clock. Every WRITE_PERIOD wall seconds, if a newer clock arrived, OUT is replaced
atomically with "<sequence> <clock seconds>"; the sequence grows by one per write, so a
reader can wait for a value that arrived after it asked."""

import os
import sys
import threading
import time

import rospy
from rosgraph_msgs.msg import Clock

WRITE_PERIOD = 0.02  # s: a reader polls every 0.1 s, so it sees a value at most this old


def main():
    out = rospy.myargv()[1]
    rospy.init_node("clock_watch", anonymous=True, disable_signals=True)
    latest = [None]
    arrived = threading.Event()

    def on_clock(msg):
        latest[0] = msg.clock.to_sec()
        arrived.set()

    rospy.Subscriber("/clock", Clock, on_clock, queue_size=1)
    sequence = 0
    while not rospy.is_shutdown():
        if not arrived.wait(1.0):
            continue
        arrived.clear()
        sequence += 1
        tmp = f"{out}.tmp"
        with open(tmp, "w") as f:
            f.write(f"{sequence} {latest[0]!r}\n")
        os.replace(tmp, out)
        time.sleep(WRITE_PERIOD)


if __name__ == "__main__":
    sys.exit(main())
