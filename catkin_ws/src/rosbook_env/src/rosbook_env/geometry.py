"""Planar pose math shared by the packages: a quaternion's yaw and a yaw's quaternion.

The one Python copy (C++ code uses tf2::getYaw). The book's own listings keep theirs, one file
per listing as the book prints them."""

import math


def quaternion_to_yaw(x, y, z, w):
    """Rotation about z (rad, in (-pi, pi]) of the quaternion (x, y, z, w), REP 103's yaw."""
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def yaw_of(q):
    """Yaw of a geometry_msgs/Quaternion, or of a dict with keys x, y, z, w (a message as
    rostopic echo or a bag reader gives it)."""
    if isinstance(q, dict):
        return quaternion_to_yaw(q["x"], q["y"], q["z"], q["w"])
    return quaternion_to_yaw(q.x, q.y, q.z, q.w)


def yaw_to_quaternion(yaw):
    """(x, y, z, w) of a rotation by `yaw` about z."""
    return (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))
