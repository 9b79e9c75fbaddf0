"""Draw a SLAM map over the world's ground truth, with the true, odometry and SLAM paths.

Maps are given as (cells, resolution, origin) with cells a 2-D array in OccupancyGrid order
(row 0 at the bottom, values -1/0/100) and origin the world pose (x, y, yaw) of cell (0, 0)'s
corner. Everything is drawn in the world frame.
"""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def cell_centres(mask, resolution, origin):
    """World coordinates of the centres of the cells where `mask` is true."""
    rows, cols = np.nonzero(mask)
    x = (cols + 0.5) * resolution
    y = (rows + 0.5) * resolution
    ox, oy, oth = origin
    c, s = math.cos(oth), math.sin(oth)
    return np.column_stack((ox + c * x - s * y, oy + s * x + c * y))


def occupied_points(cells, resolution, origin, threshold=65):
    return cell_centres(cells >= threshold, resolution, origin)


def free_points(cells, resolution, origin):
    return cell_centres(cells == 0, resolution, origin)


def draw(path, truth, slam, trajectories, title=""):
    """Write a PNG. truth/slam: (cells, resolution, origin); trajectories: {label: Trajectory}."""
    fig, ax = plt.subplots(figsize=(10, 8), dpi=100)
    marker = 72.0 / fig.dpi * 0.6
    if slam is not None:
        free = free_points(*slam)
        ax.scatter(
            free[:, 0],
            free[:, 1],
            s=marker,
            c="#dde8f5",
            marker="s",
            linewidths=0,
            label="SLAM free space",
        )
    wall = occupied_points(*truth)
    ax.scatter(
        wall[:, 0],
        wall[:, 1],
        s=marker * 2,
        c="#999999",
        marker="s",
        linewidths=0,
        label="true walls",
    )
    if slam is not None:
        occ = occupied_points(*slam)
        ax.scatter(
            occ[:, 0], occ[:, 1], s=marker, c="black", marker="s", linewidths=0, label="SLAM walls"
        )
    colours = {"ground truth": "tab:green", "odometry": "tab:red", "SLAM": "tab:blue"}
    for label, traj in trajectories.items():
        if len(traj):
            ax.plot(
                traj.poses[:, 0], traj.poses[:, 1], lw=1.2, label=label, color=colours.get(label)
            )
    ax.set_aspect("equal")
    ax.set_xlabel("x (m, world)")
    ax.set_ylabel("y (m, world)")
    ax.set_title(title)
    ax.legend(loc="upper right", fontsize=8, markerscale=6)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
