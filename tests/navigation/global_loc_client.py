#!/usr/bin/python3
"""Test and bench helper for global localization: optionally calls amcl's
global_localization, then drives the robot as a user would with teleop (a full turn in
place, then wandering: straight ahead while the Kinect's view is clear, turning in place
where it is not) for --duration sim seconds, and writes one JSON line per amcl update (sim
time, position and yaw error against the simulator's ground truth, particle count) and a
last line with the time amcl converged (from then on within --tolerance of the truth)."""

import argparse
import bisect
import json
import math
import struct
import threading

import rospy
from geometry_msgs.msg import PoseWithCovarianceStamped, Twist
from nav_msgs.msg import Odometry
from rosbook_env.geometry import yaw_of
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Empty
from tf2_msgs.msg import TFMessage

# Wandering turns in place when a reading is nearer than the Kinect's range_min (what it
# cannot measure; REP 117's -inf) plus the Kobuki's radius (0.18 m), which leaves room to stop
# from WANDER_SPEED (2 m/s^2: 2 cm) and to turn without touching the wall.
ROBOT_RADIUS = 0.18
WANDER_SPEED = 0.3  # m/s
TURN_RATE = 0.8  # rad/s: amcl updates every update_min_a (0.2 rad), four times a sim second
# s: the base stops from those speeds within 0.15 s (the Kobuki's 2 m/s^2 and 6 rad/s^2).
STOPPING = 0.3


def angle_diff(a, b):
    return math.atan2(math.sin(a - b), math.cos(a - b))


class Recorder:
    def __init__(self):
        self.lock = threading.Lock()
        self.truth = []  # (t, x, y, yaw), sim time increasing
        self.updates = []  # (t, position error, yaw error, particles, driving time)
        self.particles = None
        self.blocked = False
        self.amcl_seen = False  # amcl has its map and has published an estimate
        # Stamp of the newest scan amcl has processed: it broadcasts map -> odom for every
        # scan (dated transform_tolerance ahead), whether or not the scan was an update.
        self.amcl_scan_time = 0.0
        self.tolerance = rospy.get_param("amcl/transform_tolerance", 0.1)
        rospy.Subscriber("tf", TFMessage, self.on_tf, queue_size=50)
        self.odom = None  # (x, y, yaw), the newest
        self.drive_time = 0.0  # sim s the robot has been commanded to move
        rospy.Subscriber("odom", Odometry, self.on_odom, queue_size=5)
        rospy.Subscriber("base_pose_ground_truth", Odometry, self.on_truth, queue_size=50)
        # Raw: global localization's cloud can hold tens of thousands of poses, which rospy
        # would turn into as many Python objects only for them to be counted.
        rospy.Subscriber("particlecloud", rospy.AnyMsg, self.on_cloud, queue_size=1)
        rospy.Subscriber("amcl_pose", PoseWithCovarianceStamped, self.on_amcl, queue_size=10)
        rospy.Subscriber("scan", LaserScan, self.on_scan, queue_size=1)

    def on_truth(self, msg):
        p = msg.pose.pose
        with self.lock:
            self.truth.append(
                (msg.header.stamp.to_sec(), p.position.x, p.position.y, yaw_of(p.orientation))
            )
            # A lagging amcl's estimates still find their truth: 5 minutes at 50 Hz.
            del self.truth[:-15000]

    def on_odom(self, msg):
        p = msg.pose.pose
        self.odom = (p.position.x, p.position.y, yaw_of(p.orientation))

    def on_tf(self, msg):
        for t in msg.transforms:
            if t.child_frame_id.lstrip("/") == "odom" and t.header.frame_id.lstrip("/") == "map":
                self.amcl_scan_time = max(
                    self.amcl_scan_time, t.header.stamp.to_sec() - self.tolerance
                )

    def on_cloud(self, msg):
        # geometry_msgs/PoseArray as serialized: the header (seq, stamp, frame_id as a length
        # and its bytes), then the pose count.
        buff = msg._buff
        (frame_length,) = struct.unpack_from("<I", buff, 12)
        (count,) = struct.unpack_from("<I", buff, 16 + frame_length)
        with self.lock:
            self.particles = count

    def on_scan(self, msg):
        clearance = msg.range_min + ROBOT_RADIUS
        self.blocked = any(r < clearance for r in msg.ranges if not math.isnan(r))

    def on_amcl(self, msg):
        t = msg.header.stamp.to_sec()
        with self.lock:
            self.amcl_seen = True
            if not self.truth:
                return
            i = bisect.bisect_left([s[0] for s in self.truth], t)
            truth = self.truth[min(i, len(self.truth) - 1)]
            if abs(truth[0] - t) > 0.1:
                return
            p = msg.pose.pose
            self.updates.append(
                (
                    t,
                    math.hypot(p.position.x - truth[1], p.position.y - truth[2]),
                    abs(angle_diff(yaw_of(p.orientation), truth[3])),
                    self.particles,
                    self.drive_time,
                )
            )

    def converged_since(self, tolerance, yaw_tolerance):
        """Driving time of the first update from which every update is within tolerance
        (None if the last one is not)."""
        with self.lock:
            since = None
            for _, e, a, _, drive in self.updates:
                if e <= tolerance and a <= yaw_tolerance:
                    since = drive if since is None else since
                else:
                    since = None
            return since


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--global-localization", action="store_true")
    parser.add_argument("--duration", type=float, default=60.0, help="sim s of driving")
    parser.add_argument("--tolerance", type=float, default=0.3, help="m")
    parser.add_argument("--yaw-tolerance", type=float, default=0.3, help="rad")
    parser.add_argument(
        "--hold", type=float, default=0.0, help="stop once converged for this many s of driving"
    )
    parser.add_argument("--cmd-vel", default="cmd_vel_mux/input/navi")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("global_loc_client")
    recorder = Recorder()
    pub = rospy.Publisher(args.cmd_vel, Twist, queue_size=1)
    # amcl answers global_localization once it has its map, and it publishes amcl_pose from
    # its first scan with the map: wait for that (and for the truth and odometry), in sim time.
    while not rospy.is_shutdown() and not (recorder.amcl_seen and recorder.truth and recorder.odom):
        rospy.sleep(0.05)
    # amcl updates after update_min_d of travel or update_min_a of turning (its parameters).
    min_d = rospy.get_param("amcl/update_min_d", 0.2)
    min_a = rospy.get_param("amcl/update_min_a", math.pi / 6)
    if args.global_localization:
        rospy.wait_for_service("global_localization", timeout=60)
        rospy.ServiceProxy("global_localization", Empty)()
    with recorder.lock:
        del recorder.updates[:]  # the estimates from before the call
    t0 = rospy.get_time()
    period = 0.1  # s: a teleop's 10 Hz
    ticker = rospy.Rate(1 / period, reset=True)
    # The robot stops after each update_min_d / update_min_a of motion until amcl has
    # processed a scan taken after it stopped (and so has updated for that motion): amcl sees
    # the same motion between updates however slowly the machine runs it (the first updates
    # with global localization's large cloud are slow), so the figures do not depend on the
    # load. Time is counted in sim seconds of driving.
    anchor, stopped_at, turned = recorder.odom, None, 0.0
    spin = 2 * math.pi + min_a  # a full turn in place first, then wandering
    while not rospy.is_shutdown() and recorder.drive_time < args.duration:
        since = recorder.converged_since(args.tolerance, args.yaw_tolerance)
        if args.hold > 0 and since is not None and recorder.drive_time - since >= args.hold:
            break
        odom = recorder.odom
        moved = math.hypot(odom[0] - anchor[0], odom[1] - anchor[1])
        rotated = abs(angle_diff(odom[2], anchor[2]))
        cmd = Twist()
        if moved >= min_d or rotated >= min_a:
            stopped_at = stopped_at or rospy.get_time()
            if recorder.amcl_scan_time >= stopped_at + STOPPING:
                turned += rotated
                anchor, stopped_at = odom, None
        elif turned < spin or recorder.blocked:
            cmd.angular.z = TURN_RATE
        else:
            cmd.linear.x = WANDER_SPEED
        pub.publish(cmd)
        ticker.sleep()
        if cmd.angular.z or cmd.linear.x:
            recorder.drive_time += period
    pub.publish(Twist())
    since = recorder.converged_since(args.tolerance, args.yaw_tolerance)
    with open(args.out, "w") as out, recorder.lock:
        updates = list(recorder.updates)
        for t, e, a, n, d in updates:
            out.write(
                json.dumps({"t": t - t0, "drive": d, "error": e, "yaw_error": a, "particles": n})
                + "\n"
            )
        last = updates[-1] if updates else None
        summary = {
            "done": True,
            "sim_seconds": rospy.get_time() - t0,
            "driven": recorder.drive_time,
            "converged_after": since,
            "last_error": last[1] if last else None,
            "last_yaw_error": last[2] if last else None,
            "updates": len(updates),
        }
        out.write(json.dumps(summary) + "\n")


if __name__ == "__main__":
    main()
