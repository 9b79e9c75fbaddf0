"""Convert between map_io.OccupancyMap and nav_msgs/OccupancyGrid (needs the ROS messages)."""

import numpy as np
from geometry_msgs.msg import Pose
from nav_msgs.msg import MapMetaData, OccupancyGrid
from rosbook_env.geometry import quaternion_to_yaw, yaw_to_quaternion

from map_server.map_io import OccupancyMap


def map_metadata(omap, load_time):
    info = MapMetaData()
    info.map_load_time = load_time
    info.resolution = omap.resolution
    info.width = omap.width
    info.height = omap.height
    pose = Pose()
    pose.position.x, pose.position.y = omap.origin[0], omap.origin[1]
    q = yaw_to_quaternion(omap.origin[2])
    pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = q
    info.origin = pose
    return info


def to_occupancy_grid(omap, frame_id, stamp):
    grid = OccupancyGrid()
    grid.header.frame_id = frame_id
    grid.header.stamp = stamp
    grid.info = map_metadata(omap, stamp)
    grid.data = omap.flat().tolist()
    return grid


def from_occupancy_grid(grid):
    """OccupancyMap from a message; raises map_io.MapError when sizes disagree."""
    info = grid.info
    o = info.origin.orientation
    yaw = quaternion_to_yaw(o.x, o.y, o.z, o.w)
    origin = (info.origin.position.x, info.origin.position.y, yaw)
    cells = grid.data
    if isinstance(cells, (bytes, bytearray)):
        cells = np.frombuffer(cells, dtype=np.int8)
    return OccupancyMap.from_flat(cells, info.width, info.height, info.resolution, origin)
