#!/usr/bin/python3
"""Print the range to whatever is straight ahead, from the middle beam of `scan`."""

import rospy
from rosbook_env.master_watch import survive_master_restart
from sensor_msgs.msg import LaserScan
from wanderbot.ranges import format_range_ahead, middle_range


def scan_callback(msg):
    range_ahead = middle_range(msg.ranges, msg.range_min, msg.range_max)
    print(format_range_ahead(range_ahead), flush=True)


def main():
    rospy.init_node("range_ahead")
    survive_master_restart()  # re-registers with a restarted roscore
    rospy.Subscriber("scan", LaserScan, scan_callback, queue_size=1)
    rospy.spin()


if __name__ == "__main__":
    main()
