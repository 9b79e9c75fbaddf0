"""Accuracy figures of a SLAM run against the simulator's ground truth (numpy only, no ROS).

Inputs, whatever the entry point (score_slam, mapping_demo, the benchmarks):
- `truth`: the true base pose (/base_pose_ground_truth), a poses.Trajectory in the world;
- `odom`: odometry (/odom), a Trajectory in the odom frame;
- `slam`: SLAM's base pose in the map frame (slam_offline's trajectory, or a live run's
  map→odom ∘ odometry, see bag_tracks.live_slam_track);
- `slam_map`: the SLAM map, a grid (cells, resolution, origin in the map frame);
- `truth_map`: the world's true grid from bullet_turtlebot's `world_to_map` (truth.py).

Both trajectories are compared at SLAM's stamps that lie within the truth's span, the truth
and odometry linearly interpolated there (poses.Trajectory). Each trajectory is placed in the
world twice: by its best rigid fit onto the truth (Horn's method, the standard absolute
trajectory error) and by the true start pose (its first pose put on the truth, no fitting).
The map goes where the SLAM trajectory goes, and is judged by grids.near_wall_share.
"""

import math

import numpy as np

from rosbook_eval.grids import OCCUPIED, near_wall_share, occupied_points
from rosbook_eval.poses import best_fit_frame, compose, position_errors, rms, start_frame

PLACEMENTS = {"fit": best_fit_frame, "start": start_frame}
DEFAULT_TOLERANCE = 0.10  # metres: two cells of the 0.05 m maps


def place_grid(grid, frame):
    """The grid (cells, resolution, origin in some frame) with its origin in frame's parent."""
    cells, resolution, origin = grid
    return cells, resolution, compose(frame, tuple(origin))


def _errors(estimate, truth):
    err = position_errors(estimate, truth)
    return {
        "rms": rms(err),
        "max": float(err.max()) if len(err) else float("nan"),
        "final": float(err[-1]) if len(err) else float("nan"),
    }


def score(truth, odom, slam, slam_map, truth_map, tolerance=DEFAULT_TOLERANCE):
    """Figures of one run: a dict

        poses, distance_m, tolerance_m, occupied_cells,
        fit / start: {slam_rms, slam_max, slam_final, odom_rms, odom_max, odom_final,
                      walls, ratio, map_frame (world pose of the map frame)}

    (errors in metres, walls the share of the map's occupied cells near a true wall), plus
    the tracks in the world, placed by the best fit ("tracks": {"odometry", "SLAM"}) and the
    map placed with them ("fitted_map"), for drawing.
    """
    slam = slam.select(truth.covers(slam.t))
    if len(slam) < 2:
        raise ValueError(
            "fewer than two SLAM poses within the ground truth's time span: is the truth "
            "topic recorded for the whole run?"
        )
    odom_at_slam = odom.resampled(slam.t)
    figures = {
        "poses": len(slam),
        "distance_m": truth.length(),
        "tolerance_m": tolerance,
        "occupied_cells": int(np.count_nonzero(slam_map[0] >= OCCUPIED)),
    }
    for name, place in PLACEMENTS.items():
        world_map, world_odom = place(slam, truth), place(odom_at_slam, truth)
        slam_err = _errors(slam.transformed(world_map), truth)
        odom_err = _errors(odom_at_slam.transformed(world_odom), truth)
        placed_map = place_grid(slam_map, world_map)
        walls = near_wall_share(occupied_points(placed_map), truth_map, tolerance)
        figures[name] = {
            **{"slam_" + k: v for k, v in slam_err.items()},
            **{"odom_" + k: v for k, v in odom_err.items()},
            "ratio": slam_err["rms"] / odom_err["rms"] if odom_err["rms"] > 0 else math.inf,
            "walls": walls,
            "map_frame": world_map,
        }
        if name == "fit":
            figures["tracks"] = {
                "odometry": odom_at_slam.transformed(world_odom),
                "SLAM": slam.transformed(world_map),
            }
            figures["fitted_map"] = placed_map
    return figures


# The two entry points' JSON keys (other code and the benchmarks parse them): the same
# numbers under the names each has always used.


def score_slam_figures(figures, alignment="fit"):
    """score_slam --json: keys without suffix for `alignment`, with _fit/_start for the other."""
    out = {"poses": figures["poses"], "alignment": alignment, "tolerance": figures["tolerance_m"]}
    for name in PLACEMENTS:
        placed, suffix = figures[name], "" if name == alignment else "_" + name
        for key in ("slam_rms", "slam_max", "odom_rms", "odom_max", "ratio"):
            out[key + suffix] = placed[key]
        out["near_wall_fraction" + suffix] = placed["walls"]
    out["occupied_cells"] = figures["occupied_cells"]
    return out


def figures_json(figures):
    """mapping_demo's figures.json: keys without suffix for the best fit, _start for the
    true start pose."""
    out = {"distance_m": figures["distance_m"], "tolerance_m": figures["tolerance_m"]}
    for name, suffix in (("fit", ""), ("start", "_start")):
        placed = figures[name]
        out.update(
            {
                "odom_rms_m" + suffix: placed["odom_rms"],
                "odom_final_m" + suffix: placed["odom_final"],
                "slam_rms_m" + suffix: placed["slam_rms"],
                "slam_final_m" + suffix: placed["slam_final"],
                "walls_within_tolerance" + suffix: placed["walls"],
            }
        )
    return out
