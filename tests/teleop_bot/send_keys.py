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
import xmlrpc.client

import rosgraph
import rospy
from std_msgs.msg import String


def waited(condition, seconds=60.0, interval=0.01):
    """Whether condition() came true within `seconds` (a bound on a hang, in wall time)."""
    deadline = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > deadline:
            return False
        time.sleep(interval)
    return True


def publishers_send_to_us(sub):
    """Whether every publisher of `sub`'s topic has us in its own list of connections. Our
    side counts a connection once the publisher's header arrives, which rospy's publisher
    sends before it adds the connection to those it publishes to: a message in between is
    lost (a Twist answering the first key was)."""
    if sub.get_num_connections() == 0:
        return False
    me = rospy.get_name()
    master = rosgraph.Master(me)
    publishers = [nodes for topic, nodes in master.getSystemState()[0] if topic == sub.name]
    for node in publishers[0] if publishers else []:
        try:
            code, _, info = xmlrpc.client.ServerProxy(master.lookupNode(node)).getBusInfo(me)
        except (OSError, rosgraph.MasterError):
            return False  # a publisher going away or not up yet: ask again
        if code != 1 or not any(
            row[1] == me and row[2] == "o" and row[4] == sub.name for row in info
        ):
            return False
    return bool(publishers)


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
        return pub.get_num_connections() > 0 and (not ack_topic or publishers_send_to_us(ack))

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
