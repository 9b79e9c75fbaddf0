"""Frontiers: known free cells next to unknown ones, grouped into connected clusters."""

from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from .grid import FREE, UNKNOWN

EIGHT = np.ones((3, 3), dtype=bool)


@dataclass
class Frontier:
    label: int  # index into the label image returned with it
    size: int  # cells
    centroid: tuple  # (row, col), float


def frontier_mask(classes):
    """FREE cells with at least one UNKNOWN cell among their 8 neighbours."""
    unknown = classes == UNKNOWN
    near_unknown = ndimage.binary_dilation(unknown, structure=EIGHT)
    return (classes == FREE) & near_unknown


def cluster(mask, min_size=1):
    """8-connected clusters of `mask` with at least `min_size` cells.

    Returns (labels, frontiers): an int label image (0 = none; clusters smaller than
    min_size removed) and the Frontier list, largest first."""
    labels, count = ndimage.label(mask, structure=EIGHT)
    if count == 0:
        return labels, []
    index = np.arange(1, count + 1)
    sizes = ndimage.sum_labels(mask, labels, index).astype(int)
    centroids = ndimage.center_of_mass(mask, labels, index)
    keep = sizes >= min_size
    lookup = np.zeros(count + 1, dtype=labels.dtype)
    lookup[1:][keep] = index[keep]
    labels = lookup[labels]
    frontiers = [
        Frontier(int(i), int(s), (float(c[0]), float(c[1])))
        for i, s, c, k in zip(index, sizes, centroids, keep, strict=True)
        if k
    ]
    frontiers.sort(key=lambda f: -f.size)
    return labels, frontiers


def find_frontiers(classes, min_size=1):
    return cluster(frontier_mask(classes), min_size)


def approach_labels(labels, reach_cells):
    """Label every cell within `reach_cells` of a frontier cell with its nearest cluster's
    label (0 elsewhere): the robot observes a frontier from near it, not only on it."""
    if not labels.any():
        return np.zeros_like(labels)
    distance, (rows, cols) = ndimage.distance_transform_edt(labels == 0, return_indices=True)
    near = labels[rows, cols]
    near[distance > reach_cells] = 0
    return near
