#!/usr/bin/python3
"""The book's patrol.py (chapter 10): send move_base goals in the map frame, one waypoint
after another, forever. Ported to Python 3; waypoints fit the simulator's maze.

  rosrun patrolbot patrol.py [--waypoints FILE.yaml] [--loops N]

--waypoints: a YAML list of {x, y, yaw} (config/maze_waypoints.yaml shows the format);
--loops: stop after N loops (default: patrol until Ctrl-C). Ctrl-C cancels the current goal
and stops the robot."""

import argparse
import signal
import sys
import time

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
from patrolbot.waypoints import WaypointError, load_waypoints
from rosbook_env.master_watch import survive_master_restart

# The book's waypoints were for its Stage map; these are corridor cells of the maze world.
waypoints = [
    [(3.75, 0.75, 0.0), (0.0, 0.0, 0.7071068, 0.7071068)],
    [(2.25, 2.25, 0.0), (0.0, 0.0, 1.0, 0.0)],
    [(0.75, 0.75, 0.0), (0.0, 0.0, 0.0, 1.0)],
]


def goal_pose(pose):
    goal_pose = MoveBaseGoal()
    goal_pose.target_pose.header.frame_id = "map"
    goal_pose.target_pose.header.stamp = rospy.Time.now()
    goal_pose.target_pose.pose.position.x = pose[0][0]
    goal_pose.target_pose.pose.position.y = pose[0][1]
    goal_pose.target_pose.pose.position.z = pose[0][2]
    goal_pose.target_pose.pose.orientation.x = pose[1][0]
    goal_pose.target_pose.pose.orientation.y = pose[1][1]
    goal_pose.target_pose.pose.orientation.z = pose[1][2]
    goal_pose.target_pose.pose.orientation.w = pose[1][3]
    return goal_pose


def loop_count(text):
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text!r} must be 0 (patrol until Ctrl-C) or more")
    return value


def main():
    parser = argparse.ArgumentParser(description="Patrol waypoints with move_base.")
    parser.add_argument("--waypoints", help="YAML file of {x, y, yaw} waypoints (map frame)")
    parser.add_argument(
        "--loops", type=loop_count, default=0, help="loops to run (0: until Ctrl-C)"
    )
    args = parser.parse_args(rospy.myargv()[1:])
    poses = waypoints
    if args.waypoints:
        try:
            poses = load_waypoints(args.waypoints)
        except WaypointError as e:
            sys.exit(f"patrol.py: {e}")

    # Ctrl-C is ours (KeyboardInterrupt), not rospy's: a cancel sent from rospy's shutdown
    # hook can be lost with the connection, and the robot would drive on to the goal. The
    # handler is set explicitly, as rospy's would be: a process started in the background
    # by a non-interactive shell inherits SIGINT ignored.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    rospy.init_node("patrol", disable_signals=True)
    survive_master_restart()  # re-registers with a restarted roscore
    client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
    try:
        patrol(client, poses, args.loops)
    except KeyboardInterrupt:
        if cancel_and_confirm(client):
            rospy.loginfo("patrol: interrupted; the current goal is cancelled")
        else:
            rospy.logwarn("patrol: interrupted; move_base did not confirm the cancel")
    finally:
        rospy.signal_shutdown("patrol done")


def cancel_and_confirm(client, wall_timeout=5.0):
    """Cancel the current goal and wait until move_base says it ended, so the cancel is
    not lost when the node exits at once. Wall time: the simulator may have stopped.
    True when nothing is left running."""
    if client.gh is None:
        return True  # no goal sent yet
    client.cancel_goal()
    running = (GoalStatus.PENDING, GoalStatus.ACTIVE)  # incl. RECALLING and PREEMPTING
    deadline = time.monotonic() + wall_timeout
    while client.get_state() in running and time.monotonic() < deadline:
        time.sleep(0.05)
    return client.get_state() not in running


def patrol(client, poses, loops):
    rospy.loginfo("patrol: waiting for the move_base action server")
    client.wait_for_server()
    loop = 0
    while not rospy.is_shutdown() and (loops <= 0 or loop < loops):
        for pose in poses:
            client.send_goal(goal_pose(pose))
            client.wait_for_result()
            if rospy.is_shutdown():
                break
            state = client.get_state()
            x, y = pose[0][0], pose[0][1]
            if state == GoalStatus.SUCCEEDED:
                rospy.loginfo(f"patrol: reached ({x:.2f}, {y:.2f})")
            else:
                rospy.logwarn(
                    f"patrol: goal ({x:.2f}, {y:.2f}) ended {client.get_goal_status_text()!r}; "
                    "going on to the next waypoint"
                )
        else:
            loop += 1
            rospy.loginfo(f"patrol: loop {loop} done")


if __name__ == "__main__":
    main()
