"""Accuracy figures of a SLAM run against the simulator's ground truth."""

import math

import numpy as np

from rosbook_demo.grids import OCCUPIED, dilate, occupied_points, sample
from rosbook_demo.trajectory import (
    best_fit_frame,
    chain,
    compose,
    inverse,
    position_errors,
    rms,
)


def world_from_map(truth, odom, map_to_odom):
    """The world pose of the SLAM map frame.

    The map frame is where odometry stood when SLAM started (map→odom is the identity at the
    first scan), so it follows from the first ground-truth and odometry poses. No fitting: an
    early heading error turns the whole map and counts everywhere.
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


def _placed_figures(odom_in_world, slam_in_world, slam_map_world, truth_traj, truth_map, tol):
    odom_err = position_errors(odom_in_world, truth_traj)
    slam_err = position_errors(slam_in_world, truth_traj)
    return {
        "odom_rms_m": rms(odom_err),
        "odom_final_m": float(odom_err[-1]) if len(odom_err) else float("nan"),
        "slam_rms_m": rms(slam_err),
        "slam_final_m": float(slam_err[-1]) if len(slam_err) else float("nan"),
        "walls_within_tolerance": wall_hits(occupied_points(slam_map_world), truth_map, tol),
    }


def score(truth_traj, odom, map_to_odom, slam_map, truth_map, tolerance=0.10):
    """Figures of one run. Maps are (cells, resolution, origin-in-their-frame).

    Each trajectory is placed in the world by its best rigid fit onto the truth (the standard
    absolute trajectory error, keys without suffix), and by the true start pose (keys ending
    in _start); the map goes where the SLAM trajectory goes.
    """
    cells, resolution, origin = slam_map
    slam_in_map = chain(map_to_odom, odom)
    start_map = world_from_map(truth_traj, odom, map_to_odom)
    start_odom = compose(truth_traj.at(odom.t[0]), inverse(odom.at(odom.t[0])))
    placements = {
        "": (best_fit_frame(slam_in_map, truth_traj), best_fit_frame(odom, truth_traj)),
        "_start": (start_map, start_odom),
    }
    figures = {"distance_m": truth_traj.length(), "tolerance_m": tolerance}
    for suffix, (world_map, world_odom) in placements.items():
        slam_in_world = slam_in_map.transformed(world_map)
        odom_in_world = odom.transformed(world_odom)
        slam_map_world = (cells, resolution, compose(world_map, origin))
        placed = _placed_figures(
            odom_in_world, slam_in_world, slam_map_world, truth_traj, truth_map, tolerance
        )
        figures.update({key + suffix: value for key, value in placed.items()})
        if not suffix:
            tracks = {"odometry": odom_in_world, "SLAM": slam_in_world}
            fitted_map = slam_map_world
    return figures, tracks, fitted_map
