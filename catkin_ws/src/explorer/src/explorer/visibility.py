"""Line of sight on a grid: the sensor observes a frontier only through known free space."""

import numpy as np

from .grid import FREE


def line_of_sight(classes, start, targets):
    """For each target cell (K, 2), True when the straight segment from `start` (row,
    col) to it crosses only FREE cells (sampled at least once per cell)."""
    targets = np.asarray(targets, dtype=float).reshape(-1, 2)
    if targets.size == 0:
        return np.zeros(0, dtype=bool)
    start = np.asarray(start, dtype=float)
    delta = targets - start
    samples = int(np.abs(delta).max()) * 2 + 2
    t = np.linspace(0.0, 1.0, samples)
    rows = np.rint(start[0] + delta[:, 0:1] * t).astype(int)
    cols = np.rint(start[1] + delta[:, 1:2] * t).astype(int)
    h, w = classes.shape
    inside = (rows >= 0) & (rows < h) & (cols >= 0) & (cols < w)
    free = np.zeros(rows.shape, dtype=bool)
    free[inside] = classes[rows[inside], cols[inside]] == FREE
    return free.all(axis=1)


def sweep_headings(bearings, half_fov, max_step, scan_spacing=0.0, min_turn=0.0):
    """Headings (rad, in turning order) that bring every bearing into a sensor's field of
    view of +-half_fov, at most max_step apart: the shortest arc covering them all.

    `scan_spacing` > 0: the map takes in a scan only every `scan_spacing` radians of
    turning, at a phase nobody knows (gmapping's angularUpdate), so a sweep that merely
    touches the extreme bearings with the edge of the view may map neither. The sweep then
    reaches `scan_spacing` further at each end (the first scan mapped is at most that far
    into it, the last at most that far before its end) and turns at least `scan_spacing`
    (so that some scan is mapped), and at least `min_turn`; scans mapped every
    `scan_spacing` <= 2 half_fov leave no gap between them."""
    b = np.sort(np.mod(np.asarray(bearings, dtype=float), 2 * np.pi))
    if b.size == 0:
        return []
    gaps = np.diff(np.r_[b, b[0] + 2 * np.pi])
    widest = int(np.argmax(gaps))
    start = b[(widest + 1) % b.size]
    span = 2 * np.pi - gaps[widest]
    if scan_spacing > 0:
        turn = max(scan_spacing, min_turn, span - 2 * half_fov + 2 * scan_spacing)
        first = start + span / 2 - turn / 2
        count = max(1, int(np.ceil(turn / max_step)))
        return [float(_wrap(first + k * turn / count)) for k in range(count + 1)]
    if span <= 2 * half_fov:
        return [float(_wrap(start + span / 2))]
    first, last = start + half_fov, start + span - half_fov
    count = int(np.ceil((last - first) / max_step))
    return [float(_wrap(first + k * (last - first) / count)) for k in range(count + 1)]


def _wrap(angle):
    return np.arctan2(np.sin(angle), np.cos(angle))
