#!/usr/bin/python3
"""Test tool: record how much of a world's free area the `map` topic knows, over sim time.

    coverage_recorder.py --truth GT.yaml --start X Y YAW --out OUT.jsonl [--period 10]

GT.yaml is a ground-truth map (world frame, from `world_to_map`); the map frame is
assumed to start at the robot's start pose (X, Y, YAW in the world frame), as SLAM's does.
Each line of OUT: {"sim", "wall", "coverage", "contact", "done", "map_age"}: the share
of the ground truth's free cells reachable from the start that the map holds as known,
seconds of bumper contact so far, the explorer's ~done flag, and the map's age (sim s)."""

import argparse
import json
import math
import sys
import threading
import time
from pathlib import Path

import numpy as np
import rospy
from bullet_turtlebot.msg import BumperEvent
from explorer.map_message import decode_occupancy_grid
from std_msgs.msg import Bool

sys.path.insert(0, str(Path(__file__).resolve().parent))
from kinematic_sim import GridWorld  # noqa: E402


def truth_points(truth_yaml, start):
    """World (x, y) of the ground truth's free cells reachable from the start."""
    world = GridWorld.from_yaml(truth_yaml)
    reachable = world.free_region(start[0], start[1])
    rows, cols = np.nonzero(reachable)
    xs = world.origin_x + (cols + 0.5) * world.resolution
    ys = world.origin_y + (rows + 0.5) * world.resolution
    return xs, ys


def save_pgm(raw, path):
    """map_saver's trinary PGM (254 free, 0 occupied, 205 unknown), top row first."""
    pixels = np.full(raw.data.shape, 205, dtype=np.uint8)
    pixels[(raw.data >= 0) & (raw.data <= 25)] = 254
    pixels[raw.data >= 65] = 0
    header = f"P5\n{raw.width} {raw.height}\n255\n".encode()
    tmp = Path(path).with_suffix(".tmp")
    tmp.write_bytes(header + np.flipud(pixels).tobytes())
    tmp.replace(path)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--truth", required=True)
    parser.add_argument("--start", type=float, nargs=3, required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--period", type=float, default=10.0)
    parser.add_argument("--save-map", help="write the latest map here (PGM) at each record")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("coverage_recorder")

    x0, y0, yaw0 = args.start
    wx, wy = truth_points(args.truth, args.start)
    # World -> map frame: the inverse of the start pose.
    c, s = math.cos(yaw0), math.sin(yaw0)
    mx = c * (wx - x0) + s * (wy - y0)
    my = -s * (wx - x0) + c * (wy - y0)

    lock = threading.Lock()
    state = {"map": None, "pressed": set(), "since": None, "contact": 0.0, "done": False}

    def on_map(msg):
        raw = decode_occupancy_grid(msg._buff)
        with lock:
            state["map"] = raw

    def on_bumper(msg):
        now = rospy.get_time()
        with lock:
            was = bool(state["pressed"])
            if msg.state == BumperEvent.PRESSED:
                state["pressed"].add(msg.bumper)
            else:
                state["pressed"].discard(msg.bumper)
            if not was and state["pressed"]:
                state["since"] = now
            elif was and not state["pressed"]:
                state["contact"] += now - state["since"]

    def on_done(msg):
        with lock:
            state["done"] = msg.data

    rospy.Subscriber("map", rospy.AnyMsg, on_map, queue_size=1, buff_size=2**24)
    rospy.Subscriber("mobile_base/events/bumper", BumperEvent, on_bumper, queue_size=50)
    rospy.Subscriber("explorer/done", Bool, on_done, queue_size=1)

    def coverage(raw):
        if raw is None:
            return 0.0
        col = np.floor((mx - raw.origin[0]) / raw.resolution).astype(int)
        row = np.floor((my - raw.origin[1]) / raw.resolution).astype(int)
        inside = (row >= 0) & (row < raw.height) & (col >= 0) & (col < raw.width)
        known = np.zeros(mx.shape, dtype=bool)
        known[inside] = raw.data[row[inside], col[inside]] != -1
        return float(known.mean())

    out = open(args.out, "w")
    while not rospy.is_shutdown() and rospy.get_time() == 0:
        time.sleep(0.01)
    next_at = rospy.get_time()
    while not rospy.is_shutdown():
        now = rospy.get_time()
        if now >= next_at:
            next_at += args.period
            with lock:
                raw, contact, done = state["map"], state["contact"], state["done"]
                if state["pressed"]:
                    contact += now - state["since"]
            record = {
                "sim": now,
                "wall": time.time(),
                "coverage": coverage(raw),
                "contact": contact,
                "done": done,
                "map_age": now - raw.stamp if raw is not None else None,
            }
            out.write(json.dumps(record) + "\n")
            out.flush()
            if args.save_map and raw is not None:
                save_pgm(raw, args.save_map)
        time.sleep(0.01)


if __name__ == "__main__":
    main()
