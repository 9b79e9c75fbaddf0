"""Draw a SLAM map over the world's ground truth, with the true, odometry and SLAM paths.

Maps are grids as in rosbook_eval.grids; everything is drawn in the world frame.

The picture must show every wall, even a SLAM wall one cell thick on a world larger than
the figure has pixels. So it is built in two steps: first sampled finely enough that every
cell of both grids holds a sample (`layers`), then shrunk to at most one picture pixel per
screen pixel by taking the most important class of each block (`shrink`: a SLAM wall beats
a true wall beats SLAM free space), never by skipping rows and columns as nearest-neighbour
resampling does.
"""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from rosbook_eval.grids import OCCUPIED, cell_centres, corners, sample  # noqa: E402

# Classes of a picture pixel, in order of importance (shrink keeps the largest).
NOTHING, SLAM_FREE, TRUE_WALL, SLAM_WALL = 0, 1, 2, 3
COLOURS = np.array(
    [(255, 255, 255), (214, 228, 245), (150, 150, 150), (0, 0, 0)],
    dtype=np.uint8,
)


def _is_axis_aligned(grid, other):
    """Whether the two grids' axes are parallel (yaws equal modulo 90 degrees)."""
    turn = (grid[2][2] - other[2][2]) % (math.pi / 2)
    return min(turn, math.pi / 2 - turn) < 1e-9


def layers(truth, slam, margin=0.5):
    """The classes (NOTHING .. SLAM_WALL) of a picture of both grids in the world frame,
    row 0 at the top, and its extent (x0, x1, y0, y1) for imshow.

    Pixels are as large as the finer grid's cells, or 1/sqrt(2) of that when the SLAM grid
    is turned against the picture: a square cell of side r, however turned, holds a point
    of a lattice of spacing r/sqrt(2), so no cell of either grid falls between samples."""
    points = corners(truth)
    if slam is not None and (slam[0] != -1).any():
        points = np.vstack((points, cell_centres(slam, slam[0] != -1)))
    x0, y0 = points.min(axis=0) - margin
    x1, y1 = points.max(axis=0) + margin
    step = truth[1]
    if slam is not None:
        step = min(step, slam[1])
        if not _is_axis_aligned(slam, truth):
            step /= math.sqrt(2)
    width = max(1, int(math.ceil((x1 - x0) / step)))
    height = max(1, int(math.ceil((y1 - y0) / step)))
    xs, ys = np.meshgrid(
        x0 + (np.arange(width) + 0.5) * step, y1 - (np.arange(height) + 0.5) * step
    )
    classes = np.full(xs.shape, NOTHING, dtype=np.uint8)
    if slam is not None:
        slam_cells = sample(slam, xs, ys)
        classes[slam_cells == 0] = SLAM_FREE
    classes[sample(truth, xs, ys) >= OCCUPIED] = TRUE_WALL
    if slam is not None:
        classes[slam_cells >= OCCUPIED] = SLAM_WALL
    return classes, (x0, x0 + width * step, y1 - height * step, y1)


def shrink(classes, factor):
    """Blocks of factor x factor pixels become one, of the block's most important class
    (the largest value), so a wall one pixel thick stays. The last blocks may be partial:
    the result has ceil(height / factor) x ceil(width / factor) pixels."""
    if factor <= 1:
        return classes
    height, width = classes.shape
    padded = np.pad(classes, ((0, -height % factor), (0, -width % factor)))
    blocks = padded.reshape(padded.shape[0] // factor, factor, padded.shape[1] // factor, factor)
    return blocks.max(axis=(1, 3))


def fit(classes, extent, width_px, height_px):
    """The picture shrunk (by a whole factor) to at most width_px x height_px pixels, and
    its extent (grown by the partial last blocks: the same pixel size on both axes)."""
    height, width = classes.shape
    factor = max(1, math.ceil(width / max(width_px, 1)), math.ceil(height / max(height_px, 1)))
    small = shrink(classes, factor)
    x0, x1, y0, y1 = extent
    step = (x1 - x0) / width
    return small, (x0, x0 + small.shape[1] * factor * step, y1 - small.shape[0] * factor * step, y1)


def render(truth, slam, margin=0.5, max_size=None):
    """An RGB picture in the world frame: SLAM free space light blue, true walls grey, SLAM
    walls black. `max_size` (width, height) in pixels shrinks it to fit without losing a
    wall. Returns (image with row 0 at the top, extent for imshow)."""
    classes, extent = layers(truth, slam, margin)
    if max_size is not None:
        classes, extent = fit(classes, extent, *max_size)
    return COLOURS[classes], extent


def draw(path, truth, slam, trajectories, title=""):
    """Write a PNG. truth/slam: (cells, resolution, origin); trajectories: {label: Trajectory}.

    Returns where the map is drawn in the PNG: (left, top, right, bottom) pixels, row 0 at
    the top."""
    fig, ax = plt.subplots(figsize=(10, 8), dpi=100)
    classes, extent = layers(truth, slam)
    shown = ax.imshow(COLOURS[classes], extent=extent, interpolation="nearest")
    legend = [
        ("SLAM free space", COLOURS[SLAM_FREE]),
        ("true walls", COLOURS[TRUE_WALL]),
        ("SLAM walls", COLOURS[SLAM_WALL]),
    ]
    for label, rgb in legend:
        ax.plot([], [], "s", color=rgb / 255.0, label=label)
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
    # Now that the layout is final, shrink the picture to the pixels the axes have:
    # matplotlib's own nearest-neighbour downsampling would drop whole rows of walls.
    xlim, ylim = ax.get_xlim(), ax.get_ylim()
    fig.canvas.draw()
    box = ax.get_window_extent()
    small, small_extent = fit(classes, extent, int(box.width), int(box.height))
    shown.set_data(COLOURS[small])
    shown.set_extent(small_extent)
    ax.set_xlim(xlim)
    ax.set_ylim(ylim)
    fig.savefig(path)
    box = ax.get_window_extent()
    height = fig.bbox.height
    plt.close(fig)
    return (
        int(round(box.x0)),
        int(round(height - box.y1)),
        int(round(box.x1)),
        int(round(height - box.y0)),
    )
