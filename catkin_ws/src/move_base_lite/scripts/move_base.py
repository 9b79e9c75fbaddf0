#!/usr/bin/python3
"""move_base_lite's node: move_base's action, topics and service around the ROS-free
planner (global_planner), obstacle layer and navigator.

Action move_base (move_base_msgs/MoveBaseAction); topic move_base_simple/goal; publishes
cmd_vel (remap it to the mux's navi input), ~plan (nav_msgs/Path), ~global_costmap/costmap
and ~local_costmap/costmap (nav_msgs/OccupancyGrid); service ~make_plan (nav_msgs/GetPlan).
Everything runs on ROS time (the simulator's /clock)."""

import math
import sys
import threading
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))  # source tree runs

import actionlib  # noqa: E402
import numpy as np  # noqa: E402
import rospy  # noqa: E402
import tf2_ros  # noqa: E402
from explorer.follower import FollowerParams  # noqa: E402
from explorer.grid import GridGeometry  # noqa: E402
from explorer.recovery import RecoveryParams  # noqa: E402
from explorer.scan_safety import scan_clearance  # noqa: E402
from geometry_msgs.msg import PoseStamped, Twist  # noqa: E402
from move_base_lite.global_planner import CostmapParams, GlobalPlanner  # noqa: E402
from move_base_lite.navigator import ACTIVE, SUCCEEDED, Navigator, NavigatorParams  # noqa: E402
from move_base_lite.obstacle_layer import ObstacleLayer, scan_endpoints  # noqa: E402
from move_base_msgs.msg import (  # noqa: E402
    MoveBaseAction,
    MoveBaseActionGoal,
    MoveBaseFeedback,
    MoveBaseResult,
)
from nav_msgs.msg import OccupancyGrid  # noqa: E402
from nav_msgs.msg import Path as PathMsg
from nav_msgs.srv import GetPlan, GetPlanResponse  # noqa: E402
from rosbook_env.geometry import yaw_of, yaw_to_quaternion  # noqa: E402
from rosbook_env.master_watch import survive_master_restart  # noqa: E402
from rosbook_env.params import ParamError, count, positive  # noqa: E402
from rosbook_eval.poses import compose  # noqa: E402
from sensor_msgs.msg import LaserScan  # noqa: E402


def pose2(transform_stamped):
    """(x, y, yaw) of a geometry_msgs/TransformStamped."""
    t = transform_stamped.transform
    return t.translation.x, t.translation.y, yaw_of(t.rotation)


def set_yaw(q, yaw):
    q.x, q.y, q.z, q.w = yaw_to_quaternion(yaw)


class MoveBase:
    def __init__(self):
        get = rospy.get_param
        self.global_frame = get("~global_frame", "map").lstrip("/")
        self.base_frame = get("~robot_base_frame", "base_footprint").lstrip("/")
        # The frame localization corrects (amcl's or SLAM's map -> odom): see lookup_global.
        self.odom_frame = get("~odom_frame", "odom").lstrip("/")
        self.rate = positive("~controller_frequency", get("~controller_frequency", 10.0))
        self.costmap_params = CostmapParams(
            robot_radius=positive("~robot_radius", get("~robot_radius", 0.18)),
            inflation_radius=positive("~inflation_radius", get("~inflation_radius", 0.5)),
        )
        if self.costmap_params.inflation_radius < self.costmap_params.robot_radius:
            raise ParamError("parameter ~inflation_radius must be >= ~robot_radius")
        self.nav_params = NavigatorParams(
            xy_goal_tolerance=positive("~xy_goal_tolerance", get("~xy_goal_tolerance", 0.10)),
            yaw_goal_tolerance=positive("~yaw_goal_tolerance", get("~yaw_goal_tolerance", 0.10)),
            max_recoveries=count("~max_recoveries", get("~max_recoveries", 3)),
        )
        # Turtlebot's navigation tuning drives at up to 0.5 m/s (the Kobuki does 0.7).
        self.follower_params = FollowerParams(
            max_linear=positive("~max_vel_x", get("~max_vel_x", 0.5)),
            max_angular=positive("~max_rot_vel", get("~max_rot_vel", 1.5)),
            lookahead=positive("~lookahead", get("~lookahead", 0.5)),
        )
        self.recovery_params = RecoveryParams(turn_speed=min(0.8, self.follower_params.max_angular))
        self.obstacle_range = positive("~obstacle_range", get("~obstacle_range", 3.0))
        self.local_size = positive("~local_costmap_size", get("~local_costmap_size", 4.0))
        self.scan_timeout = 0.5  # s: older scans do not count as a clear view ahead

        self.lock = threading.RLock()
        self.planner = None
        self.layer = None
        self.clearance = None  # (stamp, metres ahead of the robot's centre)
        self.sensor_offsets = {}
        self.tf_buffer = tf2_ros.Buffer()
        self.tf_listener = tf2_ros.TransformListener(self.tf_buffer)

        self.cmd_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        self.plan_pub = rospy.Publisher("~plan", PathMsg, queue_size=1, latch=True)
        self.global_pub = rospy.Publisher(
            "~global_costmap/costmap", OccupancyGrid, queue_size=1, latch=True
        )
        self.local_pub = rospy.Publisher("~local_costmap/costmap", OccupancyGrid, queue_size=1)
        self.goal_pub = rospy.Publisher("~goal", MoveBaseActionGoal, queue_size=1)
        rospy.Subscriber("map", OccupancyGrid, self.on_map, queue_size=1)
        rospy.Subscriber("scan", LaserScan, self.on_scan, queue_size=1)
        rospy.Subscriber("move_base_simple/goal", PoseStamped, self.on_simple_goal, queue_size=1)
        rospy.Service("~make_plan", GetPlan, self.on_make_plan)
        self.server = actionlib.SimpleActionServer(
            rospy.get_name(), MoveBaseAction, execute_cb=self.execute, auto_start=False
        )
        self.server.start()
        rospy.Timer(rospy.Duration(0.5), self.publish_local_costmap, reset=True)

    # -- inputs -------------------------------------------------------------------
    def on_map(self, msg):
        if abs(yaw_of(msg.info.origin.orientation)) > 1e-6:
            rospy.logerr("move_base: maps with a rotated origin are not supported")
            return
        geometry = GridGeometry(
            msg.info.resolution,
            msg.info.origin.position.x,
            msg.info.origin.position.y,
            msg.info.width,
            msg.info.height,
        )
        values = np.frombuffer(bytes(np.array(msg.data, dtype=np.int8)), dtype=np.int8)
        values = values.reshape(geometry.height, geometry.width)
        planner = GlobalPlanner(values, geometry, self.costmap_params)
        with self.lock:
            self.planner = planner
            self.layer = ObstacleLayer(geometry, self.obstacle_range)
        rospy.loginfo(
            f"move_base: map {geometry.width}x{geometry.height} at {geometry.resolution:.3f} m"
        )
        self.global_pub.publish(self.grid_message(planner, None, msg.header.stamp))

    def on_scan(self, msg):
        frame = msg.header.frame_id.lstrip("/")
        try:
            sensor = self.lookup_global(frame, msg.header.stamp)
        except tf2_ros.TransformException as e:
            rospy.logwarn_throttle(10, f"move_base: no tf {self.global_frame} -> {frame}: {e}")
            return
        offset = self.sensor_offset(frame)
        clear = scan_clearance(msg, self.costmap_params.robot_radius, offset or 0.0)
        hits, free_ends, origin = scan_endpoints(
            msg.ranges, msg.angle_min, msg.angle_increment, msg.range_min, msg.range_max, sensor
        )
        with self.lock:
            self.clearance = (msg.header.stamp.to_sec(), clear)
            if self.layer is not None:
                self.layer.update(hits, free_ends, origin)
                self.planner.update_obstacles(self.layer.marked)

    def sensor_offset(self, frame):
        if frame not in self.sensor_offsets:
            try:
                t = self.tf_buffer.lookup_transform(self.base_frame, frame, rospy.Time(0))
            except tf2_ros.TransformException:
                return None
            self.sensor_offsets[frame] = t.transform.translation.x
        return self.sensor_offsets[frame]

    def lookup_global(self, frame, stamp):
        """(x, y, yaw) of `frame` in the global frame at `stamp`: odometry's odom -> frame
        then, on top of it, the newest global -> odom correction. One lookup global -> frame
        would interpolate global -> odom between samples its publisher dated ahead (amcl's
        transform_tolerance, 1 s in the Turtlebot's amcl.launch), so a new correction would
        count only that long after it was made: the robot stopped a converging amcl's
        older error (0.05 rad) short of a goal heading (tests/navigation). Without an odom
        frame between them (global_frame is odom), the one lookup."""
        timeout = rospy.Duration(0.2)
        if self.odom_frame in (self.global_frame, frame):
            return pose2(self.tf_buffer.lookup_transform(self.global_frame, frame, stamp, timeout))
        odometry = pose2(self.tf_buffer.lookup_transform(self.odom_frame, frame, stamp, timeout))
        try:
            correction = self.tf_buffer.lookup_transform(
                self.global_frame, self.odom_frame, rospy.Time(0)
            )
        except tf2_ros.TransformException:
            # No odom frame in this tree: the global frame reaches `frame` another way.
            return pose2(self.tf_buffer.lookup_transform(self.global_frame, frame, stamp, timeout))
        return compose(pose2(correction), odometry)

    def robot_pose(self):
        try:
            return self.lookup_global(self.base_frame, rospy.Time(0))
        except tf2_ros.TransformException as e:
            rospy.logwarn_throttle(
                10, f"move_base: waiting for tf {self.global_frame} -> {self.base_frame}: {e}"
            )
            return None

    def to_global(self, pose_stamped):
        """(x, y, yaw) of a PoseStamped in the global frame, or None with a reason."""
        frame = pose_stamped.header.frame_id.lstrip("/") or self.global_frame
        p = pose_stamped.pose
        x, y, yaw = p.position.x, p.position.y, yaw_of(p.orientation)
        if not all(math.isfinite(v) for v in (x, y, yaw)):
            return None, (
                f"the goal's position ({x:g}, {y:g}) and orientation (yaw {yaw:g}) must be "
                "finite numbers"
            )
        if frame == self.global_frame:
            return (x, y, yaw), ""
        try:
            t = self.tf_buffer.lookup_transform(
                self.global_frame, frame, rospy.Time(0), rospy.Duration(1.0)
            )
        except tf2_ros.TransformException as e:
            return None, f"cannot transform the goal from '{frame}' to '{self.global_frame}': {e}"
        tx, ty = t.transform.translation.x, t.transform.translation.y
        tyaw = yaw_of(t.transform.rotation)
        c, s = math.cos(tyaw), math.sin(tyaw)
        return (tx + c * x - s * y, ty + s * x + c * y, yaw + tyaw), ""

    # -- goals ---------------------------------------------------------------------
    def on_simple_goal(self, msg):
        # As move_base does: the rviz goal becomes a goal of our own action server.
        goal = MoveBaseActionGoal()
        goal.header.stamp = rospy.Time.now()
        goal.goal_id.stamp = goal.header.stamp
        goal.goal.target_pose = msg
        self.goal_pub.publish(goal)

    def plan(self, start, goal):
        with self.lock:
            return self.planner.plan(start, goal)

    def blocked(self, path, xy):
        with self.lock:
            return self.planner.blocked_ahead(path, xy, self.nav_params.blocked_lookahead)

    def execute(self, goal_msg):
        try:
            self.drive_goals(goal_msg)
        except rospy.ROSInterruptException:
            pass  # shutting down in the middle of a sleep: as below
        if self.server.is_active():
            # Ctrl-C while driving: the goal ends with the node, said in one line, rather
            # than with actionlib's traceback or its "did not set the goal to a terminal
            # status" warning.
            rospy.loginfo("move_base: shutting down; the current goal is aborted")
            self.server.set_aborted(MoveBaseResult(), "move_base is shutting down")

    def drive_goals(self, goal_msg):
        """The goal, then each goal that preempts it, until one ends."""
        rate = rospy.Rate(self.rate, reset=True)  # survive sim time jumping back
        while not rospy.is_shutdown():
            with self.lock:
                ready = self.planner is not None
            if ready:
                break
            rospy.logwarn_throttle(5, "move_base: waiting for the map before planning")
            rate.sleep()
        while not rospy.is_shutdown():
            outcome = self.navigate(goal_msg, rate)
            if outcome is None:  # preempted by a new goal: take it and go on
                goal_msg = self.server.accept_new_goal()
                continue
            return
        self.stop()

    def navigate(self, goal_msg, rate):
        """Drive to one goal; None when a new goal preempted it, else True when done."""
        goal, why = self.to_global(goal_msg.target_pose)
        if goal is None:
            self.server.set_aborted(MoveBaseResult(), why)
            return True
        rospy.loginfo(f"move_base: new goal ({goal[0]:.2f}, {goal[1]:.2f}, {goal[2]:.2f})")
        nav = Navigator(
            goal,
            NavigatorParams(**vars(self.nav_params)),
            FollowerParams(**vars(self.follower_params)),
            self.recovery_params,
        )
        published_path = None
        while not rospy.is_shutdown():
            if self.server.is_preempt_requested():
                self.stop()
                if self.server.is_new_goal_available():
                    return None
                self.server.set_preempted(MoveBaseResult(), "preempted")
                return True
            pose = self.robot_pose()
            if pose is not None:
                # As move_base: the pose this cycle decides on, as the goal's feedback.
                self.publish_feedback(pose)
                now = rospy.get_time()
                with self.lock:
                    clearance = self.clearance
                ahead = (
                    clearance[1] if clearance and now - clearance[0] <= self.scan_timeout else 0.0
                )
                recoveries = nav.recoveries
                command = nav.step(now, pose, ahead, self.plan, self.blocked)
                if nav.recoveries > recoveries:
                    with self.lock:
                        self.layer.clear_all()  # as move_base's clear-costmap recovery
                for event in nav.events:
                    rospy.loginfo(f"move_base: {event}")
                nav.events = []
                if nav.path is not None and nav.path is not published_path:
                    published_path = nav.path
                    self.publish_plan(nav.path, goal)
                if nav.status != ACTIVE:
                    self.stop()
                    if nav.status == SUCCEEDED:
                        rospy.loginfo("move_base: goal reached")
                        self.server.set_succeeded(MoveBaseResult(), nav.text)
                    else:
                        rospy.logwarn(f"move_base: goal aborted: {nav.text}")
                        self.server.set_aborted(MoveBaseResult(), nav.text)
                    return True
                self.send(command.linear, command.angular)
            rate.sleep()
        return True

    def send(self, linear, angular):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        self.cmd_pub.publish(twist)

    def stop(self):
        self.send(0.0, 0.0)

    # -- outputs -------------------------------------------------------------------
    def publish_feedback(self, pose):
        feedback = MoveBaseFeedback()
        feedback.base_position.header.stamp = rospy.Time.now()
        feedback.base_position.header.frame_id = self.global_frame
        feedback.base_position.pose.position.x, feedback.base_position.pose.position.y = pose[:2]
        set_yaw(feedback.base_position.pose.orientation, pose[2])
        self.server.publish_feedback(feedback)

    def publish_plan(self, path, goal):
        msg = PathMsg()
        msg.header.stamp = rospy.Time.now()
        msg.header.frame_id = self.global_frame
        for i, (x, y) in enumerate(path):
            pose = PoseStamped()
            pose.header = msg.header
            pose.pose.position.x, pose.pose.position.y = float(x), float(y)
            if i + 1 < len(path):
                yaw = math.atan2(path[i + 1][1] - y, path[i + 1][0] - x)
            else:
                yaw = goal[2]
            set_yaw(pose.pose.orientation, yaw)
            msg.poses.append(pose)
        self.plan_pub.publish(msg)

    def on_make_plan(self, req):
        with self.lock:
            ready = self.planner is not None
        if not ready:
            rospy.logwarn("move_base: ~make_plan called before the map arrived")
            return GetPlanResponse()
        if req.start.header.frame_id:
            start, _ = self.to_global(req.start)
        else:
            start = self.robot_pose()
        goal, why = self.to_global(req.goal)
        if start is None or goal is None:
            rospy.logwarn(f"move_base: ~make_plan: {why or 'no start pose'}")
            return GetPlanResponse()
        result = self.plan(start[:2], goal[:2])
        response = GetPlanResponse()
        if result.path is None:
            rospy.logwarn(f"move_base: ~make_plan: {result.reason}")
            return response
        response.plan.header.frame_id = self.global_frame
        response.plan.header.stamp = rospy.Time.now()
        for x, y in result.path:
            pose = PoseStamped()
            pose.header = response.plan.header
            pose.pose.position.x, pose.pose.position.y = float(x), float(y)
            pose.pose.orientation.w = 1.0
            response.plan.poses.append(pose)
        set_yaw(response.plan.poses[-1].pose.orientation, goal[2])
        return response

    def grid_message(self, planner, window, stamp):
        """The costmap as an OccupancyGrid: 100 lethal, 1..99 inflation cost, 0 free,
        -1 unknown; `window` (row0, col0, row1, col1) crops it (None: whole map)."""
        cm = planner.costmap
        g = planner.geometry
        row0, col0, row1, col1 = window or (0, 0, g.height, g.width)
        cost = cm.cost[row0:row1, col0:col1]
        values = np.clip(np.round(cost / max(self.costmap_params.cost_scale, 1e-9) * 98) + 1, 1, 99)
        values = np.where(cost <= 0, 0, values).astype(np.int8)
        values[planner.classes[row0:row1, col0:col1] == 1] = -1
        values[~cm.traversable[row0:row1, col0:col1] & (values >= 0)] = 100
        msg = OccupancyGrid()
        msg.header.stamp = stamp
        msg.header.frame_id = self.global_frame
        msg.info.resolution = g.resolution
        msg.info.width, msg.info.height = col1 - col0, row1 - row0
        msg.info.origin.position.x = g.origin_x + col0 * g.resolution
        msg.info.origin.position.y = g.origin_y + row0 * g.resolution
        msg.info.origin.orientation.w = 1.0
        msg.data = values.ravel().tolist()
        return msg

    def publish_local_costmap(self, _event):
        if self.local_pub.get_num_connections() == 0:
            return
        pose = self.robot_pose()
        with self.lock:
            planner = self.planner
        if pose is None or planner is None:
            return
        g = planner.geometry
        half = int(self.local_size / 2 / g.resolution)
        row, col = g.to_cell(pose[0], pose[1])
        window = (
            max(0, int(row) - half),
            max(0, int(col) - half),
            min(g.height, int(row) + half),
            min(g.width, int(col) + half),
        )
        if window[0] >= window[2] or window[1] >= window[3]:
            return
        with self.lock:
            msg = self.grid_message(planner, window, rospy.Time.now())
        self.local_pub.publish(msg)


def main():
    rospy.init_node("move_base")
    survive_master_restart()  # re-registers with a restarted roscore
    try:
        MoveBase()
    except (ParamError, ValueError) as e:
        rospy.logfatal(f"move_base: {e}")
        sys.exit(2)
    rospy.spin()


if __name__ == "__main__":
    main()
