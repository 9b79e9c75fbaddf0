import math

import matplotlib.image
import numpy as np
from rosbook_demo.overlay import (
    NOTHING,
    SLAM_FREE,
    SLAM_WALL,
    TRUE_WALL,
    draw,
    fit,
    layers,
    shrink,
)
from rosbook_eval.grids import sample


def runs(line):
    """Number of separate runs of True in a 1-D boolean array."""
    line = np.asarray(line, dtype=np.int8)
    return int(np.count_nonzero(np.diff(np.r_[0, line, 0]) == 1))


def walled(width_m, height_m, resolution, every_m, origin=(0.0, 0.0, 0.0)):
    """A SLAM-like grid: free, with one-cell walls every `every_m` metres both ways
    (starting `every_m` / 2 in); also the number of walls along x and along y."""
    rows, cols = int(round(height_m / resolution)), int(round(width_m / resolution))
    cells = np.zeros((rows, cols), dtype=np.int8)
    step = int(round(every_m / resolution))
    cells[step // 2 :: step, :] = 100
    cells[:, step // 2 :: step] = 100
    walls = (len(range(step // 2, rows, step)), len(range(step // 2, cols, step)))
    return (cells, resolution, origin), walls


def blank_truth(width_m, height_m, resolution=0.05):
    rows, cols = int(round(height_m / resolution)), int(round(width_m / resolution))
    return np.zeros((rows, cols), dtype=np.int8), resolution, (0.0, 0.0, 0.0)


def test_shrink_keeps_every_one_pixel_wall_and_ranks_the_classes():
    classes = np.full((40, 50), SLAM_FREE, dtype=np.uint8)
    classes[3::7, :] = SLAM_WALL  # one-pixel walls, 7 pixels apart
    classes[:, 5] = TRUE_WALL
    classes[0, 0] = NOTHING
    for factor in (2, 3, 4, 5, 6):
        small = shrink(classes, factor)
        assert small.shape == (math.ceil(40 / factor), math.ceil(50 / factor))
        # Every wall's row of blocks is a wall all along (walls nearer than a block merge).
        assert (small[np.arange(3, 40, 7) // factor] == SLAM_WALL).all()
        # The true wall shows wherever no SLAM wall shares its block.
        assert (small[:, 5 // factor] >= TRUE_WALL).all()
        assert small[0, 0] >= SLAM_FREE  # something beats nothing


def test_fit_stays_within_the_pixels_and_keeps_the_scale():
    classes = np.zeros((1600, 2400), dtype=np.uint8)
    small, extent = fit(classes, (0.0, 120.0, 0.0, 80.0), 700, 560)
    assert small.shape[1] <= 700 and small.shape[0] <= 560
    x0, x1, y0, y1 = extent
    assert (x1 - x0) / small.shape[1] == np.float64((y1 - y0) / small.shape[0])
    assert x0 == 0.0 and y1 == 80.0 and x1 >= 120.0 and y0 <= 0.0
    same, _ = fit(classes[:100, :100], (0.0, 5.0, 0.0, 5.0), 700, 560)
    assert same.shape == (100, 100)


def test_every_cell_of_a_turned_slam_grid_lands_on_the_picture():
    """One-cell walls of a SLAM grid turned 0.3 rad against the world: each occupied cell
    holds at least one picture pixel's centre."""
    slam, _ = walled(6.0, 4.0, 0.05, 0.5, origin=(1.0, -2.0, 0.3))
    truth = blank_truth(10.0, 8.0)
    classes, (x0, x1, y0, y1) = layers(truth, slam)
    height, width = classes.shape
    xs = x0 + (np.arange(width) + 0.5) * (x1 - x0) / width
    ys = y1 - (np.arange(height) + 0.5) * (y1 - y0) / height
    gx, gy = np.meshgrid(xs, ys)
    cells, resolution, (ox, oy, oth) = slam
    c, s = math.cos(-oth), math.sin(-oth)
    col = np.floor((c * (gx - ox) - s * (gy - oy)) / resolution).astype(int)
    row = np.floor((s * (gx - ox) + c * (gy - oy)) / resolution).astype(int)
    black = classes == SLAM_WALL
    assert (sample(slam, gx[black], gy[black]) == 100).all()
    hit = np.zeros(cells.shape, dtype=bool)
    inside = black & (row >= 0) & (row < cells.shape[0]) & (col >= 0) & (col < cells.shape[1])
    hit[row[inside], col[inside]] = True
    assert (hit == (cells == 100)).all()


def test_drawn_picture_keeps_every_one_cell_wall_of_a_world_larger_than_the_figure(tmp_path):
    """60 m x 40 m at 5 cm is 1200 x 800 cells, more than the pixels the figure gives the
    map: every one-cell SLAM wall must still be a black line in the PNG."""
    slam, (across_y, across_x) = walled(60.0, 40.0, 0.05, 0.9)
    truth = blank_truth(60.0, 40.0)
    path = tmp_path / "overlay.png"
    left, top, right, bottom = draw(path, truth, slam, {})
    image = matplotlib.image.imread(str(path))[..., :3]
    black = (image < 0.2).all(axis=2)
    inner = black[top + 3 : bottom - 3, left + 3 : right - 3]  # inside the axes' frame
    height, width = inner.shape
    assert width < 1200  # the picture really was shrunk
    # A column left of the legend (top right) crosses every wall along y; a row below it
    # every wall along x.
    for frac in (0.1, 0.3, 0.5):
        assert runs(inner[:, int(frac * width)]) == across_y
    for frac in (0.4, 0.6, 0.8):
        assert runs(inner[int(frac * height), :]) == across_x
