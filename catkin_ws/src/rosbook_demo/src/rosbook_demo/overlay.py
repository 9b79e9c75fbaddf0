"""Draw a SLAM map over the world's ground truth, with the true, odometry and SLAM paths.

Maps are grids as in rosbook_demo.grids; everything is drawn in the world frame.
"""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from rosbook_demo.grids import OCCUPIED, cell_centres, corners, sample  # noqa: E402


def render(truth, slam, margin=0.5):
    """An RGB picture in the world frame: SLAM free space light blue, true walls grey, SLAM
    walls black. Returns (image with row 0 at the top, extent for imshow)."""
    points = corners(truth)
    if slam is not None and (slam[0] != -1).any():
        points = np.vstack((points, cell_centres(slam, slam[0] != -1)))
    x0, y0 = points.min(axis=0) - margin
    x1, y1 = points.max(axis=0) + margin
    step = truth[1]
    xs, ys = np.meshgrid(np.arange(x0, x1, step) + step / 2, np.arange(y1, y0, -step) - step / 2)
    image = np.full(xs.shape + (3,), 255, dtype=np.uint8)
    if slam is not None:
        slam_cells = sample(slam, xs, ys)
        image[slam_cells == 0] = (214, 228, 245)
    image[sample(truth, xs, ys) >= OCCUPIED] = (150, 150, 150)
    if slam is not None:
        image[slam_cells >= OCCUPIED] = (0, 0, 0)
    return image, (x0, x0 + xs.shape[1] * step, y1 - ys.shape[0] * step, y1)


def draw(path, truth, slam, trajectories, title=""):
    """Write a PNG. truth/slam: (cells, resolution, origin); trajectories: {label: Trajectory}."""
    fig, ax = plt.subplots(figsize=(10, 8), dpi=100)
    image, extent = render(truth, slam)
    ax.imshow(image, extent=extent, interpolation="nearest")
    legend = [
        ("SLAM free space", (214, 228, 245)),
        ("true walls", (150, 150, 150)),
        ("SLAM walls", (0, 0, 0)),
    ]
    for label, rgb in legend:
        ax.plot([], [], "s", color=np.array(rgb) / 255.0, label=label)
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
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
