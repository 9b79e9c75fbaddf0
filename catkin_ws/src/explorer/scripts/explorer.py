#!/usr/bin/python3
"""explorer: frontier exploration on a SLAM map.

Subscribes `map` (nav_msgs/OccupancyGrid) and `scan` (sensor_msgs/LaserScan); reads the
robot pose from tf `~map_frame` -> `~base_frame`; publishes `cmd_vel` (geometry_msgs/Twist),
`~path` (nav_msgs/Path), `~goal` (geometry_msgs/PoseStamped) and `~done` (std_msgs/Bool,
latched). See the package README for the parameters.
"""

import dataclasses
import math
import os
import sys
import threading
import time

# This script has its package's name: keep folders holding an explorer.py (this script,
# catkin's devel wrapper) off the import path, or `import explorer` finds the script.
sys.path[:] = [p for p in sys.path if not os.path.isfile(os.path.join(p or ".", "explorer.py"))]

import rospy  # noqa: E402
import tf2_ros  # noqa: E402
from explorer.exploration import Explorer, ExplorerParams  # noqa: E402
from explorer.follower import FollowerParams  # noqa: E402
from explorer.map_message import MapFormatError, decode_occupancy_grid  # noqa: E402
from explorer.map_planner import MapPlanner, PlannerParams  # noqa: E402
from explorer.recovery import RecoveryParams  # noqa: E402
from explorer.scan_safety import scan_clearance  # noqa: E402
from geometry_msgs.msg import PoseStamped, Twist  # noqa: E402
from nav_msgs.msg import Path  # noqa: E402
from rosbook_env.geometry import yaw_of, yaw_to_quaternion  # noqa: E402
from rosbook_env.master_watch import survive_master_restart  # noqa: E402
from rosbook_env.params import ParamError, non_negative, positive  # noqa: E402
from sensor_msgs.msg import LaserScan  # noqa: E402
from std_msgs.msg import Bool  # noqa: E402


def param(name, default, check=positive):
    return check("~" + name, rospy.get_param("~" + name, default))


def from_params(cls, positive_fields=(), **fixed):
    """An instance of the dataclass `cls` with every field read from the private
    parameter of the same name (default: the dataclass default)."""
    values = {}
    for field in dataclasses.fields(cls):
        if field.name in fixed:
            continue
        default = field.default
        check = positive if field.name in positive_fields else non_negative
        value = param(field.name, default, check)
        values[field.name] = int(value) if isinstance(default, int) else value
    return cls(**values, **fixed)


def read_params():
    planner = from_params(
        PlannerParams,
        ("plan_resolution", "robot_radius", "inflation_radius", "reach_max", "blacklist_radius"),
    )
    if planner.inflation_radius < planner.robot_radius:
        raise ParamError("~inflation_radius must be >= ~robot_radius")
    follower = from_params(FollowerParams, ("max_linear", "max_angular", "lookahead"))
    explorer = from_params(ExplorerParams, ("replan_period", "spin_speed"))
    explorer.spin_speed = min(explorer.spin_speed, follower.max_angular)
    recovery = RecoveryParams(turn_speed=min(0.8, follower.max_angular))
    return planner, follower, explorer, recovery


class ExplorerNode:
    def __init__(self):
        planner_params, follower_params, explorer_params, recovery_params = read_params()
        self.map_frame = rospy.get_param("~map_frame", "map")
        self.base_frame = rospy.get_param("~base_frame", "base_footprint")
        self.control_rate = param("control_rate", 10.0)
        self.log_period = param("log_period", 30.0)
        self.scan_timeout = param("scan_timeout", 2.0)
        self.scan_half_width = planner_params.robot_radius + 0.04
        self.planner = MapPlanner(planner_params)
        self.explorer = Explorer(
            explorer_params,
            follower_params,
            recovery_params,
            planner_params.blacklist_radius,
            min_progress=planner_params.min_gain,
        )
        self.lock = threading.Lock()
        self.wake = threading.Event()
        self.raw_map = None
        self.prepared_stamp = None  # stamp of the map the planner holds
        self.clearance = None  # (ros time, metres ahead)
        self.sensor_offsets = {}
        self.pose = None
        self.travelled = 0.0
        self.last_log = None
        self.done_published = None
        self.idle_cycles = 0

        self.tf_buffer = tf2_ros.Buffer(rospy.Duration(10.0))
        self.tf_listener = tf2_ros.TransformListener(self.tf_buffer)
        self.cmd_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        self.path_pub = rospy.Publisher("~path", Path, queue_size=1, latch=True)
        self.goal_pub = rospy.Publisher("~goal", PoseStamped, queue_size=1, latch=True)
        self.done_pub = rospy.Publisher("~done", Bool, queue_size=1, latch=True)
        self.publish_done(False)
        # The map arrives raw and is decoded with numpy: rospy's int8[] tuples are slow.
        rospy.Subscriber("map", rospy.AnyMsg, self.map_callback, queue_size=1, buff_size=2**24)
        rospy.Subscriber("scan", LaserScan, self.scan_callback, queue_size=1, buff_size=2**20)
        # Kobuki-style bumper events (uint8 bumper, uint8 state; PRESSED = 1), read raw so
        # that kobuki_msgs and bullet_turtlebot messages both work.
        bumper_topic = rospy.get_param("~bumper_topic", "mobile_base/events/bumper")
        if bumper_topic:
            rospy.Subscriber(bumper_topic, rospy.AnyMsg, self.bumper_callback, queue_size=10)

    # -- inputs ------------------------------------------------------------------
    def map_callback(self, msg):
        try:
            raw = decode_occupancy_grid(msg._buff)
        except MapFormatError as e:
            rospy.logerr_throttle(10, f"explorer: ignoring map: {e}")
            return
        if abs(raw.origin[2]) > 1e-6:
            rospy.logerr_throttle(10, "explorer: ignoring map: rotated origins are not supported")
            return
        if raw.frame_id.lstrip("/") != self.map_frame:
            rospy.logwarn_throttle(
                30, f"explorer: map frame '{raw.frame_id}' is not ~map_frame '{self.map_frame}'"
            )
        with self.lock:
            self.raw_map = raw
        self.wake.set()

    def scan_callback(self, msg):
        offset = self.sensor_offset(msg.header.frame_id)
        if offset is None:
            return
        clear = scan_clearance(msg, self.scan_half_width, offset)
        with self.lock:
            self.clearance = (msg.header.stamp.to_sec(), clear)

    def bumper_callback(self, msg):
        data = bytes(msg._buff)
        if len(data) != 2:
            rospy.logwarn_throttle(30, "explorer: bumper message is not (uint8, uint8): ignored")
            return
        if data[1] == 1:  # PRESSED
            with self.lock:
                self.explorer.bumped(rospy.get_time())

    def sensor_offset(self, frame):
        if frame not in self.sensor_offsets:
            try:
                t = self.tf_buffer.lookup_transform(
                    self.base_frame, frame.lstrip("/"), rospy.Time(0), rospy.Duration(0.1)
                )
            except tf2_ros.TransformException as e:
                rospy.logwarn_throttle(10, f"explorer: no tf {self.base_frame} -> {frame}: {e}")
                return None
            self.sensor_offsets[frame] = t.transform.translation.x
        return self.sensor_offsets[frame]

    def robot_pose(self):
        try:
            t = self.tf_buffer.lookup_transform(self.map_frame, self.base_frame, rospy.Time(0))
        except tf2_ros.TransformException as e:
            rospy.logwarn_throttle(
                10, f"explorer: waiting for tf {self.map_frame} -> {self.base_frame}: {e}"
            )
            return None
        q = t.transform.rotation
        return t.transform.translation.x, t.transform.translation.y, yaw_of(q)

    # -- control loop (sim time) --------------------------------------------------
    def control(self, _event):
        now = rospy.get_time()
        pose = self.robot_pose()
        twist = Twist()
        if pose is not None:
            with self.lock:
                clearance = self.clearance
            if clearance is None or now - clearance[0] > self.scan_timeout:
                rospy.logwarn_throttle(10, "explorer: no recent scan: not driving forward")
                ahead = 0.0
            else:
                ahead = clearance[1]
            if self.pose is not None:
                step = math.hypot(pose[0] - self.pose[0], pose[1] - self.pose[1])
                if step < 1.0:  # ignore SLAM corrections
                    self.travelled += step
            self.pose = pose
            with self.lock:
                twist.linear.x, twist.angular.z = self.explorer.control(now, *pose, ahead)
                events = self.explorer.events
                self.explorer.events = []
                wants = self.explorer.wants_plan(now, self.map_stamp())
            self.report(events, now)
            if wants:
                self.wake.set()
        if self.explorer.done and twist.linear.x == 0 and twist.angular.z == 0:
            self.idle_cycles += 1
        else:
            self.idle_cycles = 0
        if self.idle_cycles < self.control_rate:  # then fall silent: leave the base to others
            self.cmd_pub.publish(twist)
        self.publish_done(self.explorer.done)

    def report(self, events, now):
        for event in events:
            rospy.loginfo(f"explorer: t={now:.1f} s: {event} (travelled {self.travelled:.1f} m)")
        if self.last_log is None:
            self.last_log = now
        if now - self.last_log >= self.log_period:
            self.last_log = now
            rospy.loginfo(
                f"explorer: {self.explorer.state}, {self.planner.frontier_count} frontiers, "
                f"{self.planner.known_free_area():.1f} m^2 known free, "
                f"travelled {self.travelled:.1f} m, {self.explorer.goals_reached} goals reached"
            )

    def publish_done(self, done):
        if done != self.done_published:
            self.done_published = done
            self.done_pub.publish(Bool(data=done))

    # -- planning thread ------------------------------------------------------------
    def map_stamp(self):
        return self.raw_map.stamp if self.raw_map is not None else None

    def planning_loop(self):
        while not rospy.is_shutdown():
            self.wake.wait(0.1)
            self.wake.clear()
            now = rospy.get_time()
            with self.lock:
                stamp = self.map_stamp()
                if self.pose is None or not self.explorer.wants_plan(now, stamp):
                    continue
                raw = self.raw_map
                inputs = self.explorer.plan_inputs(now, stamp)
                x, y, _ = self.pose
            started = time.monotonic()
            if stamp != self.prepared_stamp:
                self.planner.set_map(raw.data, raw.resolution, raw.origin[0], raw.origin[1])
                self.prepared_stamp = stamp
            plan = self.planner.plan(x, y, **inputs)
            rospy.logdebug(f"explorer: planned in {time.monotonic() - started:.3f} s wall")
            with self.lock:
                self.explorer.accept_plan(
                    plan,
                    rospy.get_time(),
                    stamp,
                    known_area=self.planner.known_free_area(),
                    start_blocked=self.planner.start_blocked,
                )
            if plan is not None:
                self.publish_plan(plan)

    def publish_plan(self, plan):
        stamp = rospy.Time.now()
        path = Path()
        path.header.frame_id = self.map_frame
        path.header.stamp = stamp
        for x, y in plan.path:
            pose = PoseStamped()
            pose.header = path.header
            pose.pose.position.x, pose.pose.position.y = float(x), float(y)
            pose.pose.orientation.w = 1.0
            path.poses.append(pose)
        self.path_pub.publish(path)
        goal = PoseStamped()
        goal.header = path.header
        goal.pose.position.x, goal.pose.position.y = plan.goal
        look = plan.look_yaws[len(plan.look_yaws) // 2] if plan.look_yaws else 0.0
        o = goal.pose.orientation
        o.x, o.y, o.z, o.w = yaw_to_quaternion(look)
        self.goal_pub.publish(goal)

    def run(self):
        while not rospy.is_shutdown() and rospy.get_rostime().is_zero():
            time.sleep(0.01)  # sim time: wait for /clock
        rospy.on_shutdown(lambda: self.cmd_pub.publish(Twist()))
        rospy.Timer(rospy.Duration(1.0 / self.control_rate), self.control, reset=True)
        rospy.loginfo(f"explorer: exploring ({self.map_frame} -> {self.base_frame})")
        self.planning_loop()


def main():
    rospy.init_node("explorer")
    survive_master_restart()  # re-registers with a restarted roscore
    try:
        node = ExplorerNode()
    except ParamError as e:
        rospy.logfatal(f"explorer: {e}")
        return 2
    node.run()
    return 0


if __name__ == "__main__":
    sys.exit(main())
