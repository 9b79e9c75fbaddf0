#!/usr/bin/python3
"""A stand-in for the simulated Turtlebot's sensors, for the rviz screenshot tests.

Publishes what rviz's views need, with known content so a screenshot can be checked:
tf odom → base_footprint (optionally driving a circle), odom (nav_msgs/Odometry), scan
(a wall `--wall` m ahead, 640 beams over 58°, frame camera_depth_frame),
camera/depth/points (the same wall, 1 m tall, frame camera_depth_optical_frame),
camera/rgb/image_raw (steel-blue sky over green floor) and camera/depth/image_raw
(32FC1, the wall's depth).  With --map it also publishes a latched room map on `map`
and a static tf map → odom.  Uses whatever clock the parameter server says (wall time
here).
"""

import argparse
import math

import numpy as np
import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import OccupancyGrid, Odometry
from sensor_msgs.msg import Image, LaserScan, PointCloud2, PointField

SKY = (70, 130, 180)
FLOOR = (34, 139, 34)
FOV = math.radians(58.0)
BEAMS = 640
CAMERA_HEIGHT = 0.297  # camera_depth_frame above the floor (URDF: 0.0102 + 0.287)


def quaternion_z(yaw):
    return 0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0)


def make_scan(stamp, wall):
    scan = LaserScan()
    scan.header.stamp = stamp
    scan.header.frame_id = "camera_depth_frame"
    scan.angle_min = -FOV / 2.0
    scan.angle_max = FOV / 2.0
    scan.angle_increment = FOV / (BEAMS - 1)
    scan.range_min = 0.45
    scan.range_max = 8.0
    angles = scan.angle_min + scan.angle_increment * np.arange(BEAMS)
    scan.ranges = (wall / np.cos(angles)).astype(np.float32).tolist()
    return scan


def make_cloud(stamp, wall):
    """A wall `wall` m ahead: optical frame, x right, y down, z forward."""
    half_width = wall * math.tan(FOV / 2.0)
    xs = np.arange(-half_width, half_width, 0.03, dtype=np.float32)
    ys = np.arange(-(1.0 - CAMERA_HEIGHT), CAMERA_HEIGHT, 0.03, dtype=np.float32)
    grid_x, grid_y = np.meshgrid(xs, ys)
    points = np.zeros((grid_x.size, 3), dtype=np.float32)
    points[:, 0] = grid_x.ravel()
    points[:, 1] = grid_y.ravel()
    points[:, 2] = wall
    cloud = PointCloud2()
    cloud.header.stamp = stamp
    cloud.header.frame_id = "camera_depth_optical_frame"
    cloud.height = 1
    cloud.width = len(points)
    cloud.fields = [
        PointField(name=name, offset=4 * i, datatype=PointField.FLOAT32, count=1)
        for i, name in enumerate("xyz")
    ]
    cloud.is_bigendian = False
    cloud.point_step = 12
    cloud.row_step = 12 * len(points)
    cloud.is_dense = True
    cloud.data = points.tobytes()
    return cloud


def _image(stamp, frame_id, pixels, encoding):
    """A sensor_msgs/Image of a C-contiguous array (rows of `pixels` are the image rows)."""
    image = Image()
    image.header.stamp = stamp
    image.header.frame_id = frame_id
    image.height, image.width = pixels.shape[:2]
    image.encoding = encoding
    image.step = pixels.strides[0]
    image.data = pixels.tobytes()
    return image


def make_rgb(stamp, width=320, height=240):
    pixels = np.empty((height, width, 3), dtype=np.uint8)
    pixels[: height // 2] = SKY
    pixels[height // 2 :] = FLOOR
    return _image(stamp, "camera_rgb_optical_frame", pixels, "rgb8")


def make_depth(stamp, wall, width=320, height=240):
    depth = np.full((height, width), wall, dtype=np.float32)
    return _image(stamp, "camera_depth_optical_frame", depth, "32FC1")


def make_room_map(stamp, size_m=8.0, resolution=0.05, room_m=5.0):
    """Unknown (-1) everywhere, a free (0) square room centred on the origin, walls (100)."""
    cells = int(round(size_m / resolution))
    grid = np.full((cells, cells), -1, dtype=np.int8)
    lo = int(round((size_m - room_m) / 2.0 / resolution))
    hi = cells - lo
    grid[lo:hi, lo:hi] = 100
    grid[lo + 3 : hi - 3, lo + 3 : hi - 3] = 0
    msg = OccupancyGrid()
    msg.header.stamp = stamp
    msg.header.frame_id = "map"
    msg.info.map_load_time = stamp
    msg.info.resolution = resolution
    msg.info.width = msg.info.height = cells
    msg.info.origin.position.x = msg.info.origin.position.y = -size_m / 2.0
    msg.info.origin.orientation.w = 1.0
    msg.data = grid.ravel().tolist()
    return msg


def transform(stamp, parent, child, x, y, yaw):
    tf = TransformStamped()
    tf.header.stamp = stamp
    tf.header.frame_id = parent
    tf.child_frame_id = child
    tf.transform.translation.x = x
    tf.transform.translation.y = y
    q = quaternion_z(yaw)
    tf.transform.rotation.x, tf.transform.rotation.y = q[0], q[1]
    tf.transform.rotation.z, tf.transform.rotation.w = q[2], q[3]
    return tf


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--wall", type=float, default=2.0, help="wall distance ahead (m)")
    parser.add_argument("--circle", type=float, default=0.0, help="drive a circle (radius m)")
    parser.add_argument("--map", action="store_true", help="publish a room map and map→odom")
    parser.add_argument("--rate", type=float, default=10.0)
    args = parser.parse_args(rospy.myargv()[1:])

    rospy.init_node("fake_turtlebot")
    broadcaster = tf2_ros.TransformBroadcaster()
    static = tf2_ros.StaticTransformBroadcaster()
    odom_pub = rospy.Publisher("odom", Odometry, queue_size=10)
    scan_pub = rospy.Publisher("scan", LaserScan, queue_size=5)
    cloud_pub = rospy.Publisher("camera/depth/points", PointCloud2, queue_size=2)
    rgb_pub = rospy.Publisher("camera/rgb/image_raw", Image, queue_size=2)
    depth_pub = rospy.Publisher("camera/depth/image_raw", Image, queue_size=2)
    if args.map:
        map_pub = rospy.Publisher("map", OccupancyGrid, queue_size=1, latch=True)
        map_pub.publish(make_room_map(rospy.Time.now()))
        static.sendTransform(transform(rospy.Time.now(), "map", "odom", 0.0, 0.0, 0.0))

    start = rospy.Time.now()
    rate = rospy.Rate(args.rate)
    speed = 0.3  # m/s along the circle
    while not rospy.is_shutdown():
        now = rospy.Time.now()
        x = y = yaw = 0.0
        if args.circle > 0.0:
            phase = speed * (now - start).to_sec() / args.circle
            x = args.circle * math.sin(phase)
            y = args.circle * (1.0 - math.cos(phase))
            yaw = phase
        broadcaster.sendTransform(transform(now, "odom", "base_footprint", x, y, yaw))
        odom = Odometry()
        odom.header.stamp = now
        odom.header.frame_id = "odom"
        odom.child_frame_id = "base_footprint"
        odom.pose.pose.position.x, odom.pose.pose.position.y = x, y
        q = quaternion_z(yaw)
        orientation = odom.pose.pose.orientation
        orientation.x, orientation.y, orientation.z, orientation.w = q
        odom.twist.twist.linear.x = speed if args.circle > 0.0 else 0.0
        odom_pub.publish(odom)
        scan_pub.publish(make_scan(now, args.wall))
        cloud_pub.publish(make_cloud(now, args.wall))
        rgb_pub.publish(make_rgb(now))
        depth_pub.publish(make_depth(now, args.wall))
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break


if __name__ == "__main__":
    main()
