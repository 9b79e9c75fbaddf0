#!/usr/bin/python3
"""Publish keys on `keys` (std_msgs/String) as a keyboard would: KEY@SECONDS ... where the
seconds count from the moment the `keys` subscriber is connected. `space` stands for " ".

--ack TOPIC: before each next key, wait until TOPIC has had every message the keys so far
call for (KEY@SECONDS/N: N messages, default 0): a node stalled by a loaded machine then gets
its keys one at a time, as a typist waiting for the robot would send them, and its
queue_size=1 publisher has no reason to drop one."""

import sys
import time
import warnings
from pathlib import Path

import rospy
from std_msgs.msg import String

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from delivery import a_publisher_sends_to_us  # noqa: E402


def waited(condition, seconds=60.0, interval=0.01):
    """Whether condition() came true within `seconds` (a bound on a hang, in wall time)."""
    deadline = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > deadline:
            return False
        time.sleep(interval)
    return True


def main():
    args = rospy.myargv()[1:]
    ack_topic = None
    if args[:1] == ["--ack"]:
        ack_topic, args = args[1], args[2:]
    plan = []
    for arg in args:
        key, _, spec = arg.rpartition("@")
        at, _, answers = spec.partition("/")
        plan.append((" " if key == "space" else key, float(at), int(answers or 0)))
    rospy.init_node("send_keys", anonymous=True)
    acked = []
    if ack_topic:
        ack = rospy.Subscriber(ack_topic, rospy.AnyMsg, acked.append)
    with warnings.catch_warnings():
        # No queue: publishing is synchronous, so each key is on the wire when publish()
        # returns and exiting right after the last one loses nothing.
        warnings.simplefilter("ignore", SyntaxWarning)
        pub = rospy.Publisher("keys", String)

    def connected():
        return pub.get_num_connections() > 0 and (not ack_topic or a_publisher_sends_to_us(ack))

    if not waited(connected, interval=0.02):
        missing = f"nobody subscribes to keys (or publishes {ack_topic})"
        print(f"send_keys: {missing}", file=sys.stderr)
        return 3
    # The spacing only paces the keys like a typist; the nodes handle them in order anyway.
    start = time.monotonic()
    due = 0
    for key, at, answers in plan:
        if not waited(lambda due=due: len(acked) >= due):
            print(f"send_keys: {ack_topic} had {len(acked)} of {due}", file=sys.stderr)
            return 4
        time.sleep(max(0.0, start + at - time.monotonic()))
        pub.publish(key)
        due += answers
    return 0


if __name__ == "__main__":
    sys.exit(main())
