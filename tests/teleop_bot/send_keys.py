#!/usr/bin/python3
"""Publish keys on `keys` (std_msgs/String) as a keyboard would: KEY@SECONDS ... where the
seconds count from the moment the `keys` subscriber is connected. `space` stands for " "."""

import sys
import time
import warnings

import rospy
from std_msgs.msg import String


def main():
    plan = []
    for arg in rospy.myargv()[1:]:
        key, _, at = arg.rpartition("@")
        plan.append((" " if key == "space" else key, float(at)))
    rospy.init_node("send_keys", anonymous=True)
    with warnings.catch_warnings():
        # No queue: publishing is synchronous, so each key is on the wire when publish()
        # returns and exiting right after the last one loses nothing.
        warnings.simplefilter("ignore", SyntaxWarning)
        pub = rospy.Publisher("keys", String)
    deadline = time.monotonic() + 60
    while pub.get_num_connections() == 0:
        if time.monotonic() > deadline:
            print("send_keys: nobody subscribes to keys", file=sys.stderr)
            return 3
        time.sleep(0.02)
    # The spacing only paces the keys like a typist; the nodes handle them in order anyway.
    start = time.monotonic()
    for key, at in plan:
        time.sleep(max(0.0, start + at - time.monotonic()))
        pub.publish(key)
    return 0


if __name__ == "__main__":
    sys.exit(main())
