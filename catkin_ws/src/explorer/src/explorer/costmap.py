"""Obstacle inflation: which cells the robot's centre may occupy, and what nearness costs."""

from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from .grid import FREE, OCCUPIED


@dataclass
class Costmap:
    """traversable: free cells the robot's centre may occupy; cost: extra cost per metre
    of path (0 far from obstacles, up to `cost_scale` at the lethal radius); clearance:
    metres from each cell to the nearest obstacle."""

    traversable: np.ndarray
    cost: np.ndarray
    clearance: np.ndarray


def obstacle_clearance(classes, resolution):
    """Distance (m) from each cell's centre to the nearest OCCUPIED cell's edge: negative on
    obstacles, inf everywhere when there is none."""
    occupied = classes == OCCUPIED
    if not occupied.any():
        return np.full(classes.shape, np.inf)
    return ndimage.distance_transform_edt(~occupied) * resolution - resolution / 2


def inflate(classes, resolution, robot_radius, inflation_radius, cost_scale=3.0):
    """Inflate OCCUPIED cells: cells closer than `robot_radius` are lethal; between that
    and `inflation_radius` the cost falls quadratically to zero."""
    if inflation_radius < robot_radius:
        raise ValueError("inflation_radius must be >= robot_radius")
    clearance = obstacle_clearance(classes, resolution)
    traversable = (classes == FREE) & (clearance > robot_radius)
    band = inflation_radius - robot_radius
    if band > 0:
        closeness = np.clip((inflation_radius - clearance) / band, 0.0, 1.0)
    else:
        closeness = np.zeros(classes.shape)
    cost = cost_scale * closeness**2
    return Costmap(traversable, cost, clearance)
