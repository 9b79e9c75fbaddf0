#!/usr/bin/python3
"""Test-only stand-in for SLAM: with perfect odometry, publish tf map -> odom (identity)
and a `map` (latched OccupancyGrid, frame map) built from `scan` at the tf pose.

    stand_in_mapper.py [_size:=40] [_resolution:=0.05] [_map_period:=2.0]
"""

import sys
import threading
from pathlib import Path

import numpy as np
import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import OccupancyGrid
from rosbook_env.geometry import yaw_of
from sensor_msgs.msg import LaserScan

sys.path.insert(0, str(Path(__file__).resolve().parent))
from kinematic_sim import GridWorld, Mapper  # noqa: E402


def main():
    rospy.init_node("stand_in_mapper")
    size = rospy.get_param("~size", 40.0)
    resolution = rospy.get_param("~resolution", 0.05)
    period = rospy.get_param("~map_period", 2.0)
    cells = int(round(size / resolution))
    world = GridWorld(np.zeros((cells, cells), dtype=bool), resolution, -size / 2, -size / 2)
    mapper = Mapper(world)
    lock = threading.Lock()
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer)
    static = tf2_ros.StaticTransformBroadcaster()
    identity = TransformStamped()
    identity.header.stamp = rospy.Time.now()
    identity.header.frame_id, identity.child_frame_id = "map", "odom"
    identity.transform.rotation.w = 1.0
    static.sendTransform(identity)
    pub = rospy.Publisher("map", OccupancyGrid, queue_size=1, latch=True)
    last = [None]

    def on_scan(msg):
        stamp = msg.header.stamp.to_sec()
        if last[0] is not None and stamp - last[0] < 0.2:
            return  # 5 Hz is plenty and keeps this process light at high sim speeds
        try:
            t = buffer.lookup_transform(
                "map", msg.header.frame_id, msg.header.stamp, rospy.Duration(0.2)
            )
        except tf2_ros.TransformException:
            return
        last[0] = stamp
        yaw = yaw_of(t.transform.rotation)
        angles = msg.angle_min + msg.angle_increment * np.arange(len(msg.ranges))
        ranges = np.array(msg.ranges, dtype=float)
        ranges[(ranges > msg.range_max) & np.isfinite(ranges)] = np.inf
        with lock:
            mapper.integrate(
                t.transform.translation.x,
                t.transform.translation.y,
                yaw,
                angles[::4],
                ranges[::4],
                msg.range_max,
            )

    def publish(_event):
        grid = OccupancyGrid()
        grid.header.stamp = rospy.Time.now()
        grid.header.frame_id = "map"
        grid.info.map_load_time = grid.header.stamp
        grid.info.resolution = resolution
        grid.info.width = grid.info.height = cells
        grid.info.origin.position.x = grid.info.origin.position.y = -size / 2
        grid.info.origin.orientation.w = 1.0
        with lock:
            grid.data = mapper.occupancy().ravel().tolist()
        pub.publish(grid)

    rospy.Subscriber("scan", LaserScan, on_scan, queue_size=1, buff_size=2**20)
    rospy.Timer(rospy.Duration(period), publish)
    rospy.spin()


if __name__ == "__main__":
    main()
