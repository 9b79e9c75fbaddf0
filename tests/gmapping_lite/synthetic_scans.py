#!/usr/bin/python3
"""A synthetic laser robot for slam_gmapping tests: a rectangular room with a box, exact
ray casting, perfect odometry on tf, its own /clock (so it runs under use_sim_time).

The robot turns in place one full turn, then drives along +x and back. Options bend the
sensor the ways real robots do: asymmetric scans, an upside-down or tilted laser, inf
readings for open directions, a beam count that changes, or no odometry tf at all; or
malformed scans (a layout no laser can have) for the first seconds, good ones after.
"""

import argparse
import math
import time
import warnings

import numpy as np
import rosgraph
import rospy
from geometry_msgs.msg import TransformStamped
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import LaserScan
from tf2_msgs.msg import TFMessage

# Walls of an 8 x 6 m room centred on the start, and a 0.6 m box: segments (x0, y0, x1, y1).
ROOM = [(-4, -3, 4, -3), (4, -3, 4, 3), (4, 3, -4, 3), (-4, 3, -4, -3)]
BOX = [(1.5, 1.0, 2.1, 1.0), (2.1, 1.0, 2.1, 1.6), (2.1, 1.6, 1.5, 1.6), (1.5, 1.6, 1.5, 1.0)]
LASER_XY = (0.1, 0.0)


def cast(x, y, angles, segments, range_max):
    """Ranges from (x, y) along world `angles` to the nearest segment (inf when none)."""
    dx, dy = np.cos(angles)[:, None], np.sin(angles)[:, None]
    seg = np.array(segments, dtype=float)
    sx, sy = seg[:, 2] - seg[:, 0], seg[:, 3] - seg[:, 1]
    qx, qy = seg[:, 0] - x, seg[:, 1] - y
    denom = dx * sy - dy * sx
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (qx * sy - qy * sx) / denom
        u = (qx * dy - qy * dx) / denom
    t = np.where((np.abs(denom) > 1e-12) & (t > 0) & (u >= 0) & (u <= 1), t, np.inf)
    r = t.min(axis=1)
    r[r > range_max] = np.inf
    return r


def quaternion(roll, pitch, yaw):
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
        cr * cp * cy + sr * sp * sy,
    )


def transform(stamp, parent, child, x, y, z, q):
    t = TransformStamped()
    t.header.stamp = stamp
    t.header.frame_id = parent
    t.child_frame_id = child
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = x, y, z
    (
        t.transform.rotation.x,
        t.transform.rotation.y,
        t.transform.rotation.z,
        t.transform.rotation.w,
    ) = q
    return t


def trajectory(duration):
    """Pose at time s: one turn in place (20 s), then 2 m along +x and back."""
    poses = []
    for k in range(int(duration * 50) + 1):
        s = k / 50.0
        if s < 20.0:
            poses.append((s, 0.0, 0.0, 2 * math.pi * s / 20.0))
        else:
            d = (s - 20.0) * 0.2
            x = d if d <= 2.0 else max(0.0, 4.0 - d)
            poses.append((s, x, 0.0, 0.0))
    return poses


def zero_increment(scan):
    scan.angle_increment = 0.0


def half_the_ranges(scan):
    scan.ranges = scan.ranges[: len(scan.ranges) // 2]


def swap_range_limits(scan):
    scan.range_min, scan.range_max = scan.range_max, scan.range_min


# Ways to break a scan's layout (--malformed), each caught by gmapping_lite's scanProblem.
MALFORMED = {
    "zero-increment": zero_increment,
    "short": half_the_ranges,
    "range-order": swap_range_limits,
}


def wait_for_subscribers(publishers, timeout=60.0):
    """Wait until each publisher is connected to every subscriber the master knows of (and
    to as many as `publishers` says at least), so that nobody misses the start."""
    me = rospy.get_name()
    master = rosgraph.Master(me)
    deadline = time.monotonic() + timeout
    while True:
        subscribers = dict(master.getSystemState()[1])
        missing = []
        for pub, least in publishers.items():
            # (Under sim time this node subscribes to its own /clock: one of them.)
            wanted = max(least, len(subscribers.get(pub.resolved_name, [])))
            if pub.get_num_connections() < wanted:
                missing.append(pub.resolved_name)
        if not missing:
            return
        if time.monotonic() > deadline:
            raise SystemExit(f"synthetic_scans: no subscribers on {missing} after {timeout} s")
        time.sleep(0.02)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--duration", type=float, default=40.0, help="seconds of sim time")
    p.add_argument("--speed", type=float, default=4.0, help="sim seconds per wall second")
    p.add_argument("--beams", type=int, default=360)
    p.add_argument("--angle-min", type=float, default=-2.0)
    p.add_argument("--angle-max", type=float, default=2.0)
    p.add_argument("--range-max", type=float, default=8.0)
    p.add_argument("--roll", type=float, default=0.0, help="laser roll (pi: upside down)")
    p.add_argument("--pitch", type=float, default=0.0, help="laser tilt")
    p.add_argument("--open-wall", action="store_true", help="no +x wall: those beams read inf")
    p.add_argument("--beams-after", type=int, default=0, help="beam count after half time")
    p.add_argument("--no-odom", action="store_true", help="never publish odom tf")
    p.add_argument("--start", type=float, default=100.0, help="sim time of the first tick")
    p.add_argument("--malformed", choices=sorted(MALFORMED), help="break the first scans so")
    p.add_argument(
        "--malformed-until", type=float, default=3.0, help="sim seconds of malformed scans"
    )
    args = p.parse_args(rospy.myargv()[1:])

    rospy.init_node("synthetic_scans")
    with warnings.catch_warnings():
        # No queues: publishing is synchronous, so every message is on the wire when
        # publish() returns, and exiting right after the last one loses nothing.
        warnings.simplefilter("ignore", SyntaxWarning)
        clock_pub = rospy.Publisher("/clock", Clock)
        scan_pub = rospy.Publisher("scan", LaserScan)
        tf_pub = rospy.Publisher("/tf", TFMessage)
        static_pub = rospy.Publisher("/tf_static", TFMessage, latch=True)
    walls = [w for w in ROOM if not (args.open_wall and w[0] == 4 and w[2] == 4)] + BOX

    start = rospy.Time.from_sec(args.start)
    clock_pub.publish(Clock(clock=start))
    static_pub.publish(
        TFMessage(
            [
                transform(
                    start,
                    "base_footprint",
                    "base_laser",
                    LASER_XY[0],
                    LASER_XY[1],
                    0.3,
                    quaternion(args.roll, args.pitch, 0.0),
                )
            ]
        )
    )
    wait_for_subscribers({clock_pub: 0, scan_pub: 1, tf_pub: 0 if args.no_odom else 1})

    seq = 0
    for s, x, y, th in trajectory(args.duration):
        if rospy.is_shutdown():
            break
        stamp = start + rospy.Duration.from_sec(s)
        clock_pub.publish(Clock(clock=stamp))
        if not args.no_odom:
            tf_pub.publish(
                TFMessage(
                    [transform(stamp, "odom", "base_footprint", x, y, 0, quaternion(0, 0, th))]
                )
            )
        if seq % 5 == 0:  # 10 Hz scans among 50 Hz ticks
            beams = args.beams
            if args.beams_after and s > args.duration / 2:
                beams = args.beams_after
            inc = (args.angle_max - args.angle_min) / (beams - 1)
            laser_angles = args.angle_min + inc * np.arange(beams)
            # An upside-down laser sees the world mirrored: its beam a points at -a.
            sign = -1.0 if abs(args.roll - math.pi) < 1e-6 else 1.0
            lx = x + math.cos(th) * LASER_XY[0] - math.sin(th) * LASER_XY[1]
            ly = y + math.sin(th) * LASER_XY[0] + math.cos(th) * LASER_XY[1]
            # A tilted beam travels further to cover the same horizontal distance.
            stretch = 1.0 / np.sqrt(1.0 - (np.cos(laser_angles) * math.sin(args.pitch)) ** 2)
            ranges = cast(lx, ly, th + sign * laser_angles, walls, 100.0) * stretch
            ranges[ranges > args.range_max] = np.inf
            scan = LaserScan()
            scan.header.stamp = stamp
            scan.header.frame_id = "base_laser"
            scan.angle_min, scan.angle_max, scan.angle_increment = (
                args.angle_min,
                args.angle_max,
                inc,
            )
            scan.time_increment, scan.scan_time = 0.0, 0.1
            scan.range_min, scan.range_max = 0.1, args.range_max
            scan.ranges = ranges.astype(np.float32).tolist()
            if args.malformed and s < args.malformed_until:
                MALFORMED[args.malformed](scan)
            scan_pub.publish(scan)
        seq += 1
        time.sleep(0.02 / args.speed)  # pacing only


if __name__ == "__main__":
    main()
