#!/usr/bin/python3
"""Test tool: a 4 m x 2 m walled room whose east half is unknown (`_unknown_half:=false`:
all known), as a latched `map`;
tf map -> odom -> base_footprint -> camera_depth_frame (robot at (0.5, 1.0) facing east);
and a `scan` (10 Hz, nothing in range). Wall-clock time."""

import math

import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import LaserScan

RES = 0.05


def room(unknown_half=True):
    width, height = 80, 40  # 4 m x 2 m
    data = []
    for row in range(height):
        for col in range(width):
            if row in (0, height - 1) or col in (0, width - 1):
                data.append(100)
            elif unknown_half and col >= width // 2:
                data.append(-1)
            else:
                data.append(0)
    return width, height, data


def transform(parent, child, x=0.0, y=0.0):
    t = TransformStamped()
    t.header.stamp = rospy.Time.now()
    t.header.frame_id, t.child_frame_id = parent, child
    t.transform.translation.x, t.transform.translation.y = x, y
    t.transform.rotation.w = 1.0
    return t


def main():
    rospy.init_node("fake_world")
    static = tf2_ros.StaticTransformBroadcaster()
    static.sendTransform(
        [
            transform("map", "odom"),
            transform("odom", "base_footprint", 0.5, 1.0),
            transform("base_footprint", "camera_depth_frame", -0.087),
        ]
    )
    grid = OccupancyGrid()
    grid.header.frame_id = "map"
    grid.header.stamp = rospy.Time.now()
    grid.info.resolution = RES
    grid.info.width, grid.info.height, grid.data = room(rospy.get_param("~unknown_half", True))
    grid.info.origin.orientation.w = 1.0
    pub = rospy.Publisher("map", OccupancyGrid, queue_size=1, latch=True)
    pub.publish(grid)
    scan_pub = rospy.Publisher("scan", LaserScan, queue_size=1)
    scan = LaserScan()
    scan.header.frame_id = "camera_depth_frame"
    scan.angle_min, scan.angle_max = -0.5, 0.5
    scan.angle_increment = 1.0 / 63
    scan.range_min, scan.range_max = 0.45, 8.0
    scan.ranges = [math.inf] * 64
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        scan.header.stamp = rospy.Time.now()
        scan_pub.publish(scan)
        rate.sleep()


if __name__ == "__main__":
    main()
