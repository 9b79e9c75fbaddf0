"""Accuracy figures of a SLAM run against the simulator's ground truth."""

import math

import numpy as np

from rosbook_demo.grids import OCCUPIED, dilate, occupied_points, sample
from rosbook_demo.trajectory import chain, compose, inverse, position_errors, rms


def world_from_map(truth, odom, map_to_odom):
    """The world pose of the SLAM map frame.

    The map frame is where odometry stood when SLAM started (map→odom is the identity at the
    first scan), so it follows from the first ground-truth and odometry poses. No fitting:
    the figures do not hide a drift that a best-fit alignment would absorb.
    """
    t0 = odom.t[0]
    world_to_base = truth.at(t0)
    odom_to_base = odom.at(t0)
    world_to_odom = compose(world_to_base, inverse(odom_to_base))
    return compose(world_to_odom, inverse(map_to_odom.at(t0)))


def wall_hits(points, truth, tolerance):
    """Fraction of `points` (world x, y) within `tolerance` metres of a true wall cell."""
    if not len(points):
        return float("nan")
    cells, resolution, origin = truth
    reach = int(math.ceil(tolerance / resolution))
    near = dilate(cells >= OCCUPIED, reach, resolution, tolerance).astype(np.int8)
    return float((sample((near, resolution, origin), points[:, 0], points[:, 1]) == 1).mean())


def score(truth_traj, odom, map_to_odom, slam_map, truth_map, tolerance=0.10):
    """Figures of one run. Maps are (cells, resolution, origin-in-their-frame)."""
    world_map = world_from_map(truth_traj, odom, map_to_odom)
    world_odom = compose(truth_traj.at(odom.t[0]), inverse(odom.at(odom.t[0])))
    odom_in_world = odom.transformed(world_odom)
    slam_in_world = chain(map_to_odom, odom).transformed(world_map)
    odom_err = position_errors(odom_in_world, truth_traj)
    slam_err = position_errors(slam_in_world, truth_traj)
    cells, resolution, origin = slam_map
    slam_map_world = (cells, resolution, compose(world_map, origin))
    figures = {
        "distance_m": truth_traj.length(),
        "odom_rms_m": rms(odom_err),
        "odom_final_m": float(odom_err[-1]) if len(odom_err) else float("nan"),
        "slam_rms_m": rms(slam_err),
        "slam_final_m": float(slam_err[-1]) if len(slam_err) else float("nan"),
        "walls_within_tolerance": wall_hits(occupied_points(slam_map_world), truth_map, tolerance),
        "tolerance_m": tolerance,
    }
    return figures, {"odometry": odom_in_world, "SLAM": slam_in_world}, slam_map_world
