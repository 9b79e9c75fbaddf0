#!/usr/bin/python3
"""Subscribe to topics of any type and write each message as a JSON line:
{"topic": ..., "wall": wall-clock seconds, "ros": rospy time (sim time when in use), "msg": {...}}.

Touches OUT.ready (OUT with suffix .ready) once every subscriber is connected to a publisher
or the topic's type is known, so tests can start publishing after it.
"""

import argparse
import json
import math
import sys
import threading
import time
from pathlib import Path

import genpy
import roslib.message
import rospy
import rostopic
from delivery import a_publisher_sends_to_us


def to_plain(value):
    """Turn a ROS message (or field) into JSON-serialisable data."""
    if isinstance(value, genpy.TVal):  # Time and Duration: seconds as a float
        return value.secs + value.nsecs * 1e-9
    if hasattr(value, "__slots__") and hasattr(value, "_slot_types"):
        return {name: to_plain(getattr(value, name)) for name in value.__slots__}
    if isinstance(value, bytes):
        return list(value)
    if isinstance(value, (list, tuple)):
        # A received array holds one type: numbers (a map's millions of cells) skip the walk.
        first = type(value[0]) if value else None
        if first is int or first is bool:
            return list(value)
        if first is float:
            return [v if math.isfinite(v) else str(v) for v in value]
        return [to_plain(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)  # JSON has no NaN/inf; keep them readable
    return value


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--count", type=int, help="stop after this many messages per topic")
    parser.add_argument("--duration", type=float, help="stop after this many wall seconds")
    parser.add_argument("--timeout", type=float, default=30.0)
    parser.add_argument("--name", default="topic_probe")
    parser.add_argument(
        "--type",
        action="append",
        default=[],
        metavar="TOPIC=PKG/MSG",
        help="subscribe with this type instead of waiting for a publisher to tell it",
    )
    parser.add_argument("topics", nargs="+")
    args = parser.parse_args(rospy.myargv()[1:])

    rospy.init_node(args.name, anonymous=True, disable_signals=True)
    out = open(args.out, "w")
    lock = threading.Lock()
    counts = {t: 0 for t in args.topics}
    done = threading.Event()

    def callback(msg, topic):
        with lock:
            if args.count is not None and counts[topic] >= args.count:
                return
            counts[topic] += 1
            record = {
                "topic": topic,
                "wall": time.time(),
                "ros": rospy.get_time(),
                "msg": to_plain(msg),
            }
            out.write(json.dumps(record) + "\n")
            out.flush()
            if args.count is not None and all(c >= args.count for c in counts.values()):
                done.set()

    given = dict(item.split("=", 1) for item in args.type)
    deadline = time.monotonic() + args.timeout
    subscribers = []
    for topic in args.topics:
        # get_topic_class matches the master's list literally: resolve relative names.
        resolved = rospy.resolve_name(topic)
        msg_class, real_topic = None, resolved
        if topic in given:
            msg_class = roslib.message.get_message_class(given[topic])
        while msg_class is None:
            msg_class, real_topic, _ = rostopic.get_topic_class(resolved, blocking=False)
            if msg_class is None:
                if time.monotonic() > deadline:
                    print(f"topic_probe: no publisher of {topic} appeared", file=sys.stderr)
                    return 3
                time.sleep(0.05)
        subscribers.append(rospy.Subscriber(real_topic, msg_class, callback, topic))
    # Wait until a publisher of each topic has added us, so nothing published next is missed.
    while not all(a_publisher_sends_to_us(s) for s in subscribers):
        if time.monotonic() > deadline:
            break
        time.sleep(0.02)
    Path(args.out).with_suffix(".ready").touch()

    stop_at = time.monotonic() + args.duration if args.duration else deadline
    while not done.is_set() and time.monotonic() < min(stop_at, deadline):
        time.sleep(0.02)
    with lock:
        out.close()
    if args.count is not None and not done.is_set() and not args.duration:
        print(f"topic_probe: timed out; got {counts}", file=sys.stderr)
        return 4
    return 0


if __name__ == "__main__":
    sys.exit(main())
