"""Grid planning: Dijkstra over traversable cells (scipy's C implementation), path
extraction, and the choice of the frontier to explore next."""

import math
from dataclasses import dataclass

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import dijkstra

from .frontiers import spread_labels
from .grid import FREE
from .visibility import line_of_sight

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
    seen: np.ndarray  # (K, 2) row, col of the frontier cells in sight from the goal


def choose_goal(
    field,
    classes,
    labels,
    frontiers,
    resolution,
    reach=(0.6, 2.5),
    info_weight=0.5,
    info_cap=8.0,
    excluded=None,
    tries=40,
    near=None,
):
    """Pick the best frontier and the cell to observe it from.

    Score = path cost - info_weight * min(gain, info_cap) (metres; gain in m^2 of unknown
    space behind the frontier). The goal cell is the cheapest reachable cell that sees
    some of the frontier's cells in a straight line through free space at a distance
    within `reach` (metres). `excluded` masks cells that must not be goals (blacklist).
    Returns None when no frontier can be observed from a reachable cell. `near`: the
    labels spread through free space (spread_labels) if already computed for this map;
    labels of frontiers not in `frontiers` are skipped."""
    if not frontiers:
        return None
    if near is None:
        near = approach_labels(labels, classes, resolution, reach[1])
    candidate = (near > 0) & np.isfinite(field.distance)
    if excluded is not None:
        candidate &= ~excluded
    if not candidate.any():
        return None
    by_label = {f.label: f for f in frontiers}
    rows, cols = np.nonzero(candidate)
    cand_labels = near[rows, cols]
    cand_cost = field.distance[rows, cols]
    order = np.lexsort((cand_cost, cand_labels))
    rows, cols, cand_labels, cand_cost = (a[order] for a in (rows, cols, cand_labels, cand_cost))
    starts = np.flatnonzero(np.r_[True, cand_labels[1:] != cand_labels[:-1]])
    ends = np.r_[starts[1:], len(cand_labels)]

    def bonus(label):
        return info_weight * min(by_label[label].gain * resolution**2, info_cap)

    # Branch and bound: the cheapest candidate of a frontier bounds its score from below.
    groups = [
        (float(cand_cost[a]) - bonus(int(cand_labels[a])), a, b)
        for a, b in zip(starts, ends, strict=True)
        if int(cand_labels[a]) in by_label
    ]
    groups.sort()
    frontier_cells = _cells_by_label(labels)
    best = None
    for bound, a, b in groups:
        if best is not None and bound >= best.score:
            break
        label = int(cand_labels[a])
        targets = frontier_cells[label]
        for i in _probe_order(b - a, tries):
            k = a + i
            score = float(cand_cost[k]) - bonus(label)
            if best is not None and score >= best.score:
                break
            cell = (int(rows[k]), int(cols[k]))
            dist = np.hypot(targets[:, 0] - cell[0], targets[:, 1] - cell[1]) * resolution
            in_range = targets[(dist >= reach[0]) & (dist <= reach[1])]
            seen = in_range[line_of_sight(classes, cell, in_range)]
            if len(seen):
                frontier = by_label[label]
                gain = frontier.gain * resolution**2
                best = GoalChoice(
                    label, cell, float(cand_cost[k]), score, frontier.size, gain, seen
                )
                break
    return best


def approach_labels(labels, classes, resolution, reach):
    """Each free cell within `reach` metres (through free space) of a frontier, labelled
    with that frontier: where the robot might observe it from."""
    steps = max(1, int(np.ceil(reach / resolution)))
    return spread_labels(labels, classes == FREE, steps)[0]


def _cells_by_label(labels):
    rows, cols = np.nonzero(labels)
    values = labels[rows, cols]
    order = np.argsort(values, kind="stable")
    rows, cols, values = rows[order], cols[order], values[order]
    splits = np.flatnonzero(np.diff(values)) + 1
    cells = np.column_stack([rows, cols])
    return {
        int(group_values[0]): group
        for group, group_values in zip(
            np.split(cells, splits), np.split(values, splits), strict=True
        )
    }


def _probe_order(count, tries):
    """Candidate indices to test, cheapest first: the first few, then spread out."""
    if count <= tries:
        return range(count)
    head = np.arange(tries // 2)
    tail = np.linspace(tries // 2, count - 1, tries - tries // 2).astype(int)
    return np.unique(np.concatenate([head, tail]))
