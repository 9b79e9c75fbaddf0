import math

import numpy as np
import pytest
from explorer.grid import FREE, OCCUPIED, UNKNOWN
from explorer.visibility import line_of_sight, sweep_headings


def test_line_of_sight_is_blocked_by_walls_and_unknown():
    classes = np.full((10, 10), FREE, dtype=np.uint8)
    classes[2:8, 5] = OCCUPIED
    classes[9, 5] = UNKNOWN
    targets = [(5, 8), (0, 6), (5, 3)]
    assert line_of_sight(classes, (5, 1), targets).tolist() == [False, True, True]
    assert line_of_sight(classes, (9, 1), [(9, 9), (7, 9)]).tolist() == [False, True]
    assert line_of_sight(classes, (5, 1), []).size == 0


def test_sweep_of_a_narrow_spread_is_one_heading():
    assert sweep_headings([0.1, 0.2, 0.3], 0.45, 0.9) == [pytest.approx(0.2)]


def test_sweep_covers_a_wide_spread_in_steps_across_pi():
    bearings = [math.pi - 0.5, -math.pi + 0.5, math.pi]  # 1 rad wide, around +-pi
    headings = sweep_headings(bearings, 0.3, 0.6)
    assert len(headings) == 2
    for b in bearings:
        assert min(abs(math.remainder(b - h, 2 * math.pi)) for h in headings) <= 0.3 + 1e-9
    steps = [
        abs(math.remainder(b - a, 2 * math.pi))
        for a, b in zip(headings, headings[1:], strict=False)
    ]
    assert all(s <= 0.6 + 1e-9 for s in steps)


def test_sweep_of_nothing_is_empty():
    assert sweep_headings([], 0.45, 0.9) == []


def mapped_views(headings, spacing, phase, step=0.01):
    """Headings of the scans a mapper takes in while the robot turns through `headings`
    (from the first): one every `spacing` radians of turning; `phase` is the turning done
    since the last scan mapped before the sweep began (0 <= phase < spacing)."""
    path = []
    for a, b in zip(headings, headings[1:], strict=False):
        delta = math.remainder(b - a, 2 * math.pi)
        count = max(1, int(abs(delta) / step))
        path += [a + delta * k / count for k in range(count)]
    path.append(headings[-1])
    mapped, turned = [], phase
    for a, b in zip(path, path[1:], strict=False):
        turned += abs(math.remainder(b - a, 2 * math.pi))
        if turned >= spacing - 1e-9:
            mapped.append(b)
            turned = 0.0
    return mapped


def covers(views, bearings, half_fov):
    return bool(views) and all(
        min(abs(math.remainder(b - v, 2 * math.pi)) for v in views) <= half_fov + 1e-6
        for b in bearings
    )


PHASES = np.linspace(0.0, 0.436, 23, endpoint=False)
# The Kinect's half field of view (29 deg): the planner's view model (0.45 rad) keeps
# 0.06 rad within it, for the turn between the scan that reaches angularUpdate and the
# one that follows (mapped_views steps 0.05 rad, a scan at 10 Hz turning 0.5 rad/s).
KINECT_HALF_FOV = math.radians(29)


@pytest.mark.parametrize(
    "bearings", [[0.2], [0.1, 0.3], [-0.4, 0.4], [-0.6, 0.0, 0.7], [3.0, -3.0, 2.2]]
)
def test_sweep_for_a_map_that_takes_in_a_scan_per_turn_covers_every_bearing(bearings):
    """gmapping maps a scan only after the robot turned angularUpdate (0.436 rad): with
    that spacing given, the scans mapped during the sweep cover every bearing, whatever
    the phase, and the sweep turns at least min_turn."""
    half_fov, spacing = 0.45, 0.436
    headings = sweep_headings(bearings, half_fov, 2 * half_fov, spacing, min_turn=0.5)
    pairs = zip(headings, headings[1:], strict=False)
    steps = [abs(math.remainder(b - a, 2 * math.pi)) for a, b in pairs]
    assert sum(steps) >= 0.5 - 1e-9 and max(steps) <= 2 * half_fov + 1e-9
    for phase in PHASES:
        views = mapped_views(headings, spacing, phase, step=0.05)
        assert covers(views, bearings, KINECT_HALF_FOV), phase


def test_a_sweep_that_only_touches_the_extreme_bearings_maps_too_little():
    """Why the spacing matters: the plain sweep (the view's edge just reaching the extreme
    bearings) over a 1.3 rad spread maps scans that miss one end, at every phase."""
    bearings = [-0.6, 0.0, 0.7]
    plain = sweep_headings(bearings, 0.45, 0.9)
    assert all(not covers(mapped_views(plain, 0.436, phase), bearings, 0.45) for phase in PHASES)
