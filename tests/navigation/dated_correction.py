#!/usr/bin/python3
"""Test helper: the transforms amcl publishes, without amcl. odom -> base_footprint (the
robot standing still) stamped now, and map -> odom dated --ahead seconds ahead, as amcl
dates it by transform_tolerance, at 10 Hz. On a message on switch_correction (std_msgs/Empty)
the correction moves the robot by +0.5 m in x, and the time of that change is published
(latched) on correction_switched (std_msgs/Float64, ROS seconds)."""

import argparse

import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped
from std_msgs.msg import Empty, Float64


def transform(stamp, parent, child, x):
    t = TransformStamped()
    t.header.stamp = stamp
    t.header.frame_id = parent
    t.child_frame_id = child
    t.transform.translation.x = x
    t.transform.rotation.w = 1.0
    return t


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--x", type=float, required=True, help="map -> odom x before the switch")
    parser.add_argument("--ahead", type=float, default=5.0)
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("dated_correction")
    broadcaster = tf2_ros.TransformBroadcaster()
    switched = rospy.Publisher("correction_switched", Float64, queue_size=1, latch=True)
    asked = []
    rospy.Subscriber("switch_correction", Empty, lambda _: asked.append(True), queue_size=1)
    switch_time = None
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        now = rospy.Time.now()
        if switch_time is None and asked:
            switch_time = now
        x = args.x + (0.5 if switch_time is not None else 0.0)
        broadcaster.sendTransform(
            [
                transform(now, "odom", "base_footprint", 0.0),
                transform(now + rospy.Duration(args.ahead), "map", "odom", x),
            ]
        )
        if switch_time == now:
            switched.publish(Float64(now.to_sec()))
        rate.sleep()


if __name__ == "__main__":
    main()
