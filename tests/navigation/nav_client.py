#!/usr/bin/python3
"""Test and bench helper: optionally sets amcl's initial pose (or scatters its particles
with global_localization) and turns in place to let it converge, sends move_base goals one
after another (or one goal and a second that preempts it), and writes one JSON line per
goal: the final state and status text, the sim seconds it took, the true pose at the end
(the simulator's base_pose_ground_truth, in the world frame the test maps share), and the
largest and last amcl position error against the truth while it drove."""

import argparse
import bisect
import json
import math
import threading
import time

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseWithCovarianceStamped, Twist
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
from nav_msgs.msg import Odometry
from rosbook_env.geometry import yaw_of
from rosbook_eval.poses import wrap
from std_srvs.srv import Empty

STATES = {v: k for k, v in vars(GoalStatus).items() if k.isupper() and isinstance(v, int)}


class Recorder:
    def __init__(self):
        self.lock = threading.Lock()
        self.truth = []  # (t, x, y, yaw), in arrival order (sim time increases)
        self.errors = []  # (t, amcl position error)
        self.yaw_errors = []  # (t, amcl heading error, amcl's own heading sd)
        self.obstacle = None  # (x, y): record how near the robot's centre comes to it
        self.nearest = float("inf")
        rospy.Subscriber("base_pose_ground_truth", Odometry, self.on_truth, queue_size=50)
        rospy.Subscriber("amcl_pose", PoseWithCovarianceStamped, self.on_amcl, queue_size=10)

    def on_truth(self, msg):
        p = msg.pose.pose
        with self.lock:
            self.truth.append(
                (msg.header.stamp.to_sec(), p.position.x, p.position.y, yaw_of(p.orientation))
            )
            del self.truth[:-2000]
            if self.obstacle is not None:
                d = math.hypot(p.position.x - self.obstacle[0], p.position.y - self.obstacle[1])
                self.nearest = min(self.nearest, d)

    def truth_at(self, t):
        with self.lock:
            if not self.truth:
                return None
            i = bisect.bisect_left([s[0] for s in self.truth], t)
            i = min(max(i, 0), len(self.truth) - 1)
            return self.truth[i]

    def on_amcl(self, msg):
        t = msg.header.stamp.to_sec()
        truth = self.truth_at(t)
        if truth is None or abs(truth[0] - t) > 0.1:
            return
        p = msg.pose.pose.position
        yaw = yaw_of(msg.pose.pose.orientation)
        with self.lock:
            self.errors.append((t, math.hypot(p.x - truth[1], p.y - truth[2])))
            self.yaw_errors.append(
                (t, abs(wrap(yaw - truth[3])), math.sqrt(max(msg.pose.covariance[35], 0.0)))
            )

    def errors_since(self, t0):
        with self.lock:
            return [e for t, e in self.errors if t >= t0]

    def yaw_errors_since(self, t0):
        with self.lock:
            return [(e, sd) for t, e, sd in self.yaw_errors if t >= t0]


def goal_of(x, y, yaw):
    goal = MoveBaseGoal()
    goal.target_pose.header.frame_id = "map"
    goal.target_pose.header.stamp = rospy.Time.now()
    goal.target_pose.pose.position.x = x
    goal.target_pose.pose.position.y = y
    goal.target_pose.pose.orientation.z = math.sin(yaw / 2)
    goal.target_pose.pose.orientation.w = math.cos(yaw / 2)
    return goal


def turn_in_place(recorder, seconds, topic, rate=0.8):
    """Turn left at `rate` rad/s for `seconds` of sim time (amcl updates on rotation), then
    stop; returns amcl's error against the truth at the end."""
    pub = rospy.Publisher(topic, Twist, queue_size=1)
    t0 = rospy.get_time()
    spin = Twist()
    spin.angular.z = rate
    ticker = rospy.Rate(10, reset=True)
    while not rospy.is_shutdown() and rospy.get_time() - t0 < seconds:
        pub.publish(spin)
        ticker.sleep()
    pub.publish(Twist())
    errors = recorder.errors_since(t0)
    return {
        "settled": seconds,
        "amcl_last_error": errors[-1] if errors else None,
        "amcl_updates": len(errors),
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--goal", action="append", default=[], help="x,y,yaw (repeatable)")
    parser.add_argument("--initial-pose", help="x,y,yaw sent on initialpose first")
    parser.add_argument(
        "--global-localization", action="store_true", help="call amcl's global_localization first"
    )
    parser.add_argument("--settle", type=float, default=0.0, help="sim s to turn in place first")
    parser.add_argument("--settle-cmd-vel", default="cmd_vel_mux/input/navi", help="for --settle")
    parser.add_argument("--preempt-after", type=float, help="sim s before goal 2 preempts goal 1")
    parser.add_argument("--obstacle", help="x,y: report the robot's nearest approach to it")
    parser.add_argument("--goal-timeout", type=float, default=120.0, help="sim s per goal")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("nav_client")
    recorder = Recorder()
    if args.obstacle:
        recorder.obstacle = tuple(float(v) for v in args.obstacle.split(","))
    client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
    client.wait_for_server()
    while not rospy.is_shutdown() and rospy.get_time() == 0:
        rospy.sleep(0.05)
    out = open(args.out, "a")
    if args.initial_pose:
        x, y, yaw = (float(v) for v in args.initial_pose.split(","))
        pub = rospy.Publisher("initialpose", PoseWithCovarianceStamped, queue_size=1, latch=True)
        msg = PoseWithCovarianceStamped()
        msg.header.frame_id = "map"
        msg.header.stamp = rospy.Time.now()
        msg.pose.pose.position.x, msg.pose.pose.position.y = x, y
        msg.pose.pose.orientation.z, msg.pose.pose.orientation.w = (
            math.sin(yaw / 2),
            math.cos(yaw / 2),
        )
        # rviz's 2D Pose Estimate covariance: 0.5 m and pi/12 rad standard deviations.
        msg.pose.covariance[0] = msg.pose.covariance[7] = 0.25
        msg.pose.covariance[35] = (math.pi / 12) ** 2
        rospy.sleep(1.0)  # sim time: let amcl's subscription connect (latched anyway)
        pub.publish(msg)
        rospy.sleep(1.0)
    if args.global_localization:
        rospy.wait_for_service("global_localization", timeout=60)
        rospy.ServiceProxy("global_localization", Empty)()
    if args.settle > 0:
        out.write(json.dumps(turn_in_place(recorder, args.settle, args.settle_cmd_vel)) + "\n")
    goals = [tuple(float(v) for v in g.split(",")) for g in args.goal]
    if args.preempt_after is not None:
        t0 = rospy.get_time()
        client.send_goal(goal_of(*goals[0]))
        # The preemption's delay counts from move_base's taking the goal: on a loaded machine
        # its acceptance can take longer than the delay itself (wall time bounds the wait).
        deadline = time.monotonic() + 60.0
        while client.get_state() == GoalStatus.PENDING and time.monotonic() < deadline:
            time.sleep(0.02)
        rospy.sleep(args.preempt_after)
        first_state = client.get_state()
        goals = goals[1:]
        out.write(json.dumps({"preempted_goal_state_before": STATES.get(first_state)}) + "\n")
    for goal in goals:
        t0 = rospy.get_time()
        decided = []  # move_base's own pose each cycle (feedback base_position)
        client.send_goal(
            goal_of(*goal), feedback_cb=lambda fb, decided=decided: decided.append(fb.base_position)
        )
        finished = client.wait_for_result(rospy.Duration(args.goal_timeout))
        t1 = rospy.get_time()
        truth = recorder.truth_at(t1)
        errors = recorder.errors_since(t0)
        yaw_errors = recorder.yaw_errors_since(t0)
        own = decided[-1].pose if decided else None
        record = {
            "goal": goal,
            "finished": finished,
            "state": STATES.get(client.get_state()),
            "text": client.get_goal_status_text(),
            "sim_seconds": t1 - t0,
            "truth": truth[1:] if truth else None,
            "position_error": math.hypot(truth[1] - goal[0], truth[2] - goal[1]) if truth else None,
            "yaw_error": abs(math.atan2(math.sin(truth[3] - goal[2]), math.cos(truth[3] - goal[2])))
            if truth
            else None,
            "amcl_max_error": max(errors) if errors else None,
            "amcl_last_error": errors[-1] if errors else None,
            "amcl_updates": len(errors),
            # move_base's own pose when it decided, for diagnosis: its last feedback as the
            # client got it (actionlib drops a feedback that arrives after the result, so at
            # times it is the cycle before).
            "own_position_error": math.hypot(own.position.x - goal[0], own.position.y - goal[1])
            if own
            else None,
            "own_yaw_error": abs(wrap(yaw_of(own.orientation) - goal[2])) if own else None,
            "amcl_max_yaw_error": max(e for e, _ in yaw_errors) if yaw_errors else None,
            "amcl_last_yaw_error": yaw_errors[-1][0] if yaw_errors else None,
            "amcl_last_yaw_sd": yaw_errors[-1][1] if yaw_errors else None,
            "nearest_to_obstacle": recorder.nearest if recorder.obstacle else None,
        }
        if not finished:
            client.cancel_goal()
        out.write(json.dumps(record) + "\n")
        out.flush()
    out.write(json.dumps({"done": True}) + "\n")
    out.close()


if __name__ == "__main__":
    main()
