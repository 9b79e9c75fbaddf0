#!/usr/bin/python3
"""The book's patrol.py (chapter 10): send move_base goals in the map frame, one waypoint
after another, forever. Ported to Python 3; waypoints fit the simulator's maze.

  rosrun patrolbot patrol.py [--waypoints FILE.yaml] [--loops N]

--waypoints: a YAML list of {x, y, yaw} (config/maze_waypoints.yaml shows the format);
--loops: stop after N loops (default: patrol until Ctrl-C). Ctrl-C cancels the current goal
and stops the robot."""

import argparse
import sys

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
from patrolbot.waypoints import WaypointError, load_waypoints

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


def main():
    parser = argparse.ArgumentParser(description="Patrol waypoints with move_base.")
    parser.add_argument("--waypoints", help="YAML file of {x, y, yaw} waypoints (map frame)")
    parser.add_argument("--loops", type=int, default=0, help="loops to run (0: until Ctrl-C)")
    args = parser.parse_args(rospy.myargv()[1:])
    poses = waypoints
    if args.waypoints:
        try:
            poses = load_waypoints(args.waypoints)
        except WaypointError as e:
            sys.exit(f"patrol.py: {e}")

    rospy.init_node("patrol")
    client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
    rospy.on_shutdown(client.cancel_all_goals)  # Ctrl-C: the robot stops where it is
    rospy.loginfo("patrol: waiting for the move_base action server")
    client.wait_for_server()
    loop = 0
    while not rospy.is_shutdown() and (args.loops <= 0 or loop < args.loops):
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
