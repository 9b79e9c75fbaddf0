"""Ground-truth comparison for score_slam: trajectories and maps (numpy only, no ROS)."""

import math

import numpy as np
from map_server.map_io import load_map


def load_map_yaml(path):
    """A map_server YAML as {"resolution", "origin", "grid"}: grid rows bottom-up, -1/0/100.

    map_server's own loader reads it, so scoring sees exactly what map_server serves."""
    loaded = load_map(path)
    return {
        "resolution": loaded.resolution,
        "origin": [loaded.origin[0], loaded.origin[1]],
        "grid": loaded.data.astype(np.int16),
    }


def rasterize_primitives(truth, world):
    """Draw a simulator world's boxes and cylinders into a truth map (footprints)."""
    res, (ox, oy), grid = truth["resolution"], truth["origin"], truth["grid"]
    h, w = grid.shape
    ys, xs = np.mgrid[0:h, 0:w]
    cx, cy = ox + (xs + 0.5) * res, oy + (ys + 0.5) * res
    for box in world.get("boxes", []) or []:
        px, py = box["pose"][0], box["pose"][1]
        yaw = box["pose"][5] if len(box["pose"]) > 5 else 0.0
        sx, sy = box["size"][0] / 2, box["size"][1] / 2
        dx, dy = cx - px, cy - py
        u = math.cos(yaw) * dx + math.sin(yaw) * dy
        v = -math.sin(yaw) * dx + math.cos(yaw) * dy
        grid[(np.abs(u) <= sx + res / 2) & (np.abs(v) <= sy + res / 2)] = 100
    for cyl in world.get("cylinders", []) or []:
        px, py = cyl["position"][0], cyl["position"][1]
        grid[np.hypot(cx - px, cy - py) <= cyl["radius"] + res / 2] = 100


def interpolate_poses(poses, stamps, keep_stamps=False):
    """Poses (t, x, y, yaw rows) linearly interpolated at `stamps` (clamped at the ends)."""
    poses = np.asarray(poses)
    stamps = np.asarray(stamps, dtype=float)
    yaw = np.unwrap(poses[:, 3])
    out = np.column_stack(
        [
            stamps,
            np.interp(stamps, poses[:, 0], poses[:, 1]),
            np.interp(stamps, poses[:, 0], poses[:, 2]),
            np.interp(stamps, poses[:, 0], yaw),
        ]
    )
    return out if keep_stamps else out[:, 1:]


def compose(a, b):
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], a[2] + b[2])


def inverse(a):
    c, s = math.cos(a[2]), math.sin(a[2])
    return (-c * a[0] - s * a[1], s * a[0] - c * a[1], -a[2])


def align_to_first(truth_start, odom_start):
    """world <- map: the map frame is odometry's frame, placed by the true start pose."""
    return compose(tuple(truth_start), inverse(tuple(odom_start)))


def align_best_fit(poses, truth):
    """world <- frame of (t, x, y, yaw) `poses`: the rigid motion that best fits their positions
    onto the true ones at the same stamps (least squares, Horn's method; no scale), as the
    standard absolute trajectory error (ATE) aligns a trajectory before measuring it."""
    poses = np.asarray(poses)
    inside = (poses[:, 0] >= truth[0, 0]) & (poses[:, 0] <= truth[-1, 0])
    src = poses[inside, 1:3]
    dst = interpolate_poses(truth, poses[inside, 0])[:, :2]
    if len(src) < 2:
        raise ValueError("need two poses within the ground truth's time span to align")
    ms, md = src.mean(axis=0), dst.mean(axis=0)
    a, b = src - ms, dst - md
    yaw = math.atan2(np.sum(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]), np.sum(a * b))
    c, s = math.cos(yaw), math.sin(yaw)
    return (md[0] - (c * ms[0] - s * ms[1]), md[1] - (s * ms[0] + c * ms[1]), yaw)


def transform_points(to_world, xy):
    c, s = math.cos(to_world[2]), math.sin(to_world[2])
    xy = np.asarray(xy, dtype=float).reshape(-1, 2)
    return np.column_stack(
        [to_world[0] + c * xy[:, 0] - s * xy[:, 1], to_world[1] + s * xy[:, 0] + c * xy[:, 1]]
    )


def trajectory_error(poses, truth, to_world):
    """RMS and max position error of (t, x, y, yaw) poses in the map frame vs truth."""
    poses = np.asarray(poses)
    inside = (poses[:, 0] >= truth[0, 0]) & (poses[:, 0] <= truth[-1, 0])
    poses = poses[inside]
    world = transform_points(to_world, poses[:, 1:3])
    true_xy = interpolate_poses(truth, poses[:, 0])[:, :2]
    err = np.hypot(*(world - true_xy).T)
    return float(np.sqrt(np.mean(err**2))), float(err.max())


def occupied_points(slam_map, to_world):
    res, (ox, oy) = slam_map["resolution"], slam_map["origin"]
    rows, cols = np.nonzero(slam_map["grid"] >= 65)
    xy = np.column_stack([ox + (cols + 0.5) * res, oy + (rows + 0.5) * res])
    return transform_points(to_world, xy)


def map_accuracy(points, truth, tolerance):
    """Share of points within `tolerance` of an occupied truth cell (of its square)."""
    if len(points) == 0:
        return 0.0
    res, (ox, oy), grid = truth["resolution"], truth["origin"], truth["grid"]
    occupied = grid >= 65
    h, w = grid.shape
    reach = int(math.ceil(tolerance / res)) + 1
    near = 0
    for x, y in points:
        i, j = int(math.floor((x - ox) / res)), int(math.floor((y - oy) / res))
        j0, j1, i0, i1 = (
            max(0, j - reach),
            min(h, j + reach + 1),
            max(0, i - reach),
            min(w, i + reach + 1),
        )
        if j0 >= j1 or i0 >= i1:
            continue
        jj, ii = np.nonzero(occupied[j0:j1, i0:i1])
        if len(ii) == 0:
            continue
        x0, y0 = ox + (ii + i0) * res, oy + (jj + j0) * res
        ex = np.maximum(0, np.maximum(x0 - x, x - (x0 + res)))
        ey = np.maximum(0, np.maximum(y0 - y, y - (y0 + res)))
        if np.min(np.hypot(ex, ey)) <= tolerance:
            near += 1
    return near / len(points)
