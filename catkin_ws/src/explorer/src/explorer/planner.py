"""Grid planning: Dijkstra over traversable cells (scipy's C implementation), path
extraction, and the choice of the frontier to explore next."""

import math
from dataclasses import dataclass

import numpy as np
from scipy import ndimage
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import dijkstra

from .frontiers import spread_labels
from .grid import FREE

# Half of the 8-neighbourhood (the graph is undirected): (drow, dcol).
STEPS = ((0, 1), (1, 0), (1, 1), (1, -1))


@dataclass
class DistanceField:
    """Path cost from the start to every cell (inf: unreachable) and how to get there."""

    distance: np.ndarray  # metres, weighted by the costmap, shape of the grid
    predecessor: np.ndarray  # node index of the previous cell, -9999 at the start/unreached
    index: np.ndarray  # node index of each cell, -1 where not traversable
    cells: np.ndarray  # (N, 2) row, col of each node
    start: tuple  # the (row, col) the search started from


def _shifted(a, dr, dc):
    """Views a[r, c] and a[r + dr, c + dc] over the cells where both exist."""
    h, w = a.shape
    r0, r1 = max(0, -dr), h - max(0, dr)
    c0, c1 = max(0, -dc), w - max(0, dc)
    return a[r0:r1, c0:c1], a[r0 + dr : r1 + dr, c0 + dc : c1 + dc]


def build_graph(traversable, cost, resolution):
    """Sparse undirected graph of 8-connected traversable cells. An edge costs its length
    times (1 + mean cell cost); diagonals need both side cells traversable (no corner
    cutting)."""
    index = np.full(traversable.shape, -1, dtype=np.int64)
    cells = np.argwhere(traversable)
    index[cells[:, 0], cells[:, 1]] = np.arange(len(cells))
    sources, targets, weights = [], [], []
    for dr, dc in STEPS:
        a, b = _shifted(index, dr, dc)
        ok = (a >= 0) & (b >= 0)
        if dr and dc:
            # The side cells (r + dr, c) and (r, c + dc) of each pair (r, c) -> (r + dr, c + dc).
            h, w = index.shape
            r0, r1 = max(0, -dr), h - max(0, dr)
            c0, c1 = max(0, -dc), w - max(0, dc)
            side1 = traversable[r0 + dr : r1 + dr, c0:c1]
            side2 = traversable[r0:r1, c0 + dc : c1 + dc]
            ok &= side1 & side2
        ca, cb = _shifted(cost, dr, dc)
        length = resolution * math.hypot(dr, dc)
        sources.append(a[ok])
        targets.append(b[ok])
        weights.append(length * (1.0 + 0.5 * (ca[ok] + cb[ok])))
    n = len(cells)
    graph = coo_matrix(
        (np.concatenate(weights), (np.concatenate(sources), np.concatenate(targets))),
        shape=(n, n),
    ).tocsr()
    return graph, index, cells


def nearest_traversable(traversable, cell, max_cells):
    """The traversable cell nearest to `cell` within `max_cells`, or None."""
    r, c = cell
    h, w = traversable.shape
    r0, r1 = max(0, r - max_cells), min(h, r + max_cells + 1)
    c0, c1 = max(0, c - max_cells), min(w, c + max_cells + 1)
    window = np.argwhere(traversable[r0:r1, c0:c1])
    if window.size == 0:
        return None
    window += (r0, c0)
    d2 = ((window - (r, c)) ** 2).sum(axis=1)
    best = int(np.argmin(d2))
    if d2[best] > max_cells * max_cells:
        return None
    return int(window[best, 0]), int(window[best, 1])


def distance_field(costmap, start, resolution, snap_cells=5):
    """Dijkstra from `start` (row, col); when the start is not traversable (the robot
    brushed an inflated wall) search from the nearest traversable cell. None if none."""
    traversable = costmap.traversable
    h, w = traversable.shape
    r, c = start
    if not (0 <= r < h and 0 <= c < w and traversable[r, c]):
        snapped = nearest_traversable(traversable, (r, c), snap_cells)
        if snapped is None:
            return None
        r, c = snapped
    graph, index, cells = build_graph(traversable, costmap.cost, resolution)
    dist, pred = dijkstra(graph, directed=False, indices=int(index[r, c]), return_predecessors=True)
    distance = np.full(traversable.shape, np.inf)
    distance[cells[:, 0], cells[:, 1]] = dist
    return DistanceField(distance, pred, index, cells, (r, c))


def extract_path(field, goal):
    """Cells (K, 2) from the start to `goal` (row, col), or None if unreachable."""
    node = int(field.index[goal])
    if node < 0 or not np.isfinite(field.distance[goal]):
        return None
    nodes = [node]
    while field.predecessor[node] >= 0:
        node = int(field.predecessor[node])
        nodes.append(node)
    return field.cells[np.array(nodes[::-1])]


@dataclass
class GoalChoice:
    label: int
    cell: tuple  # (row, col)
    cost: float  # path cost, metres
    score: float
    size: int  # frontier cells
    gain: float  # m^2 of unknown space the frontier opens onto


def choose_goal(
    field,
    classes,
    labels,
    frontiers,
    resolution,
    reach=(0.4, 1.2),
    info_weight=0.5,
    info_cap=8.0,
    excluded=None,
):
    """Pick the frontier with the best score = path cost - info_weight * min(gain,
    info_cap) (metres and square metres of unknown space behind it), and the cheapest
    reachable cell that observes it from a geodesic distance within `reach` (metres).
    `excluded` masks cells that must not be goals (blacklist). None if none is reachable."""
    if not frontiers:
        return None
    min_steps = int(round(reach[0] / resolution))
    max_steps = max(1, int(round(reach[1] / resolution)))
    near, steps = spread_labels(labels, classes == FREE, max_steps)
    candidate = (near > 0) & np.isfinite(field.distance) & (steps >= min_steps)
    if excluded is not None:
        candidate &= ~excluded
    near = np.where(candidate, near, 0)
    if not near.any():
        return None
    by_label = {f.label: f for f in frontiers}
    # Only labels with candidates: scipy reports 0 at (0, 0) for an absent label.
    index = np.array([label for label in np.unique(near[near > 0]) if label in by_label])
    if index.size == 0:
        return None
    masked = np.where(candidate, field.distance, np.inf)
    costs = ndimage.minimum(masked, near, index)
    positions = ndimage.minimum_position(masked, near, index)
    best = None
    for label, cost, pos in zip(index, costs, positions, strict=True):
        if not np.isfinite(cost):
            continue
        frontier = by_label[label]
        gain = frontier.gain * resolution**2
        score = cost - info_weight * min(gain, info_cap)
        if best is None or score < best.score:
            cell = (int(pos[0]), int(pos[1]))
            best = GoalChoice(int(label), cell, float(cost), score, frontier.size, gain)
    return best
