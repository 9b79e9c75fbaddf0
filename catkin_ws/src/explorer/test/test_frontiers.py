import numpy as np
import pytest
from explorer.costmap import obstacle_clearance
from explorer.frontiers import (
    closed_gaps,
    find_frontiers,
    frontier_mask,
    information_gain,
    spread_labels,
)
from explorer.grid import FREE, OCCUPIED, UNKNOWN


def test_frontier_is_free_next_to_unknown():
    classes = np.full((5, 6), UNKNOWN, dtype=np.uint8)
    classes[:, :3] = FREE
    classes[0, :3] = OCCUPIED
    mask = frontier_mask(classes)
    assert mask[1:, 2].all()  # free cells touching the unknown half
    assert not mask[:, :2].any() and not mask[:, 3:].any()
    assert not mask[0].any()  # occupied cells are never frontiers


def test_diagonal_contact_counts():
    classes = np.full((3, 3), FREE, dtype=np.uint8)
    classes[0, 0] = UNKNOWN
    assert frontier_mask(classes)[1, 1]


def test_clusters_are_8_connected_and_small_ones_dropped():
    classes = np.full((10, 10), FREE, dtype=np.uint8)
    classes[0, 0:4] = UNKNOWN  # frontier: row 1 cols 0..4 and (0, 4) -> 6 cells
    classes[9, 9] = UNKNOWN  # frontier of 3 cells in the far corner
    labels, frontiers = find_frontiers(classes, min_size=4)
    assert len(frontiers) == 1
    assert frontiers[0].size == 6
    assert (labels > 0).sum() == 6
    assert frontiers[0].centroid == pytest.approx((5 / 6, 14 / 6))
    _, both = find_frontiers(classes, min_size=1)
    assert [f.size for f in both] == [6, 3]  # largest first


def test_no_unknown_means_no_frontier():
    labels, frontiers = find_frontiers(np.full((4, 4), FREE, dtype=np.uint8))
    assert frontiers == [] and not labels.any()


def test_spread_is_geodesic_and_bounded():
    labels = np.zeros((7, 7), dtype=int)
    labels[3, 0] = 5
    through = np.ones((7, 7), dtype=bool)
    through[:, 2] = False  # a wall
    through[6, 2] = True  # with a gap at the bottom
    spread, steps = spread_labels(labels, through, 4)
    assert spread[3, 1] == 5 and steps[3, 1] == 1
    assert spread[3, 3] == 0  # behind the wall: the way round is longer than 4 steps
    assert spread[6, 2] == 5 and steps[6, 2] == 3
    assert steps[0, 0] == 3 and steps[3, 0] == 0


def test_gain_counts_unknown_space_behind_the_frontier():
    classes = np.full((20, 20), UNKNOWN, dtype=np.uint8)
    classes[:, :5] = FREE
    classes[8:12, 5:15] = FREE  # a short corridor into the unknown ...
    classes[7, 5:15] = classes[12, 5:15] = OCCUPIED  # ... with walls
    labels, frontiers = find_frontiers(classes)
    information_gain(classes, labels, frontiers, steps=3)
    gains = sorted(f.gain for f in frontiers)
    assert gains[-1] > gains[0] > 0


def test_closed_gaps_closes_what_the_robot_cannot_pass_and_keeps_doors():
    classes = np.full((12, 30), FREE, dtype=np.uint8)
    classes[5, :] = OCCUPIED  # a wall, 0.1 m cells ...
    classes[5, 3:5] = FREE  # ... with a 0.2 m gap (narrower than a 0.36 m robot)
    classes[5, 15:24] = FREE  # and a 0.9 m door
    clearance = obstacle_clearance(classes, 0.1)
    closed = closed_gaps(clearance, 0.1, 0.36)
    assert closed[5, 3:5].all()
    assert not closed[5, 15:24].any()
    assert closed[classes == OCCUPIED].all()
    assert not closed_gaps(clearance, 0.1, 0.0)[5, 3:5].any()


def test_gain_leaves_out_unknown_space_behind_a_face_mapped_with_gaps():
    """A box's face seen with gaps (cells no beam ended on) lets its unknown inside touch
    the free space: without the closed gaps it counts as gain, though no view enters it."""
    classes = np.full((30, 30), FREE, dtype=np.uint8)
    classes[10:20, 10:20] = UNKNOWN  # the inside of a box ...
    classes[9, 9:21] = OCCUPIED  # ... whose near face the scan mapped ...
    classes[9, 12] = classes[9, 16] = UNKNOWN  # ... with two one-cell gaps no beam ended in
    classes[10:20, 9] = OCCUPIED
    classes[10:20, 20] = OCCUPIED
    classes[20, 9:21] = OCCUPIED
    labels, frontiers = find_frontiers(classes)
    assert frontiers
    information_gain(classes, labels, frontiers, steps=30)
    assert sum(f.gain for f in frontiers) >= 50
    blocked = closed_gaps(obstacle_clearance(classes, 0.1), 0.1, 0.36)
    information_gain(classes, labels, frontiers, steps=30, blocked=blocked)
    assert all(f.gain == 0 for f in frontiers)
    # A doorway wide enough to drive through keeps its gain.
    classes[9, 12:18] = FREE
    labels, frontiers = find_frontiers(classes)
    blocked = closed_gaps(obstacle_clearance(classes, 0.1), 0.1, 0.36)
    information_gain(classes, labels, frontiers, 30, blocked)
    assert max(f.gain for f in frontiers) >= 50
