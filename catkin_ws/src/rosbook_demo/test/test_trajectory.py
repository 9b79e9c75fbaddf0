import math

import numpy as np
import pytest
from rosbook_demo.trajectory import (
    Trajectory,
    best_fit_frame,
    chain,
    compose,
    inverse,
    position_errors,
    rms,
    wrap,
)


def close(a, b, tol=1e-9):
    return all(abs(x - y) < tol for x, y in zip(a, b, strict=True))


def test_compose_then_inverse_is_identity():
    a = (1.0, -2.0, 0.7)
    assert close(compose(a, inverse(a)), (0.0, 0.0, 0.0))
    assert close(compose(inverse(a), a), (0.0, 0.0, 0.0))


def test_compose_rotates_the_inner_offset():
    assert close(compose((1.0, 0.0, math.pi / 2), (1.0, 0.0, 0.0)), (1.0, 1.0, math.pi / 2))


def test_wrap_keeps_angles_in_minus_pi_pi():
    assert abs(wrap(3 * math.pi) - math.pi) < 1e-9 or abs(wrap(3 * math.pi) + math.pi) < 1e-9
    assert wrap(-0.5) == pytest.approx(-0.5)


def test_at_takes_the_latest_pose_not_after_the_stamp():
    traj = Trajectory([2.0, 1.0, 3.0], [(2, 0, 0), (1, 0, 0), (3, 0, 0)])
    assert traj.at(0.5)[0] == 1  # before the start: the first pose
    assert traj.at(2.5)[0] == 2
    assert traj.at(9.0)[0] == 3


def test_length_sums_steps():
    traj = Trajectory([0, 1, 2], [(0, 0, 0), (3, 4, 0), (3, 0, 0)])
    assert traj.length() == pytest.approx(9.0)


def test_chain_applies_the_correction_in_force_at_each_stamp():
    correction = Trajectory([0.0, 5.0], [(0, 0, 0), (1.0, 0, 0)])
    odom = Trajectory([1.0, 6.0], [(0, 0, 0), (0, 0, 0)])
    assert [p[0] for p in chain(correction, odom).poses] == [0.0, 1.0]


def test_position_errors_and_rms():
    truth = Trajectory([0, 1], [(0, 0, 0), (1, 0, 0)])
    estimate = Trajectory([0, 1], [(0, 3, 0), (1, 4, 0)])
    assert list(position_errors(estimate, truth)) == [3.0, 4.0]
    assert rms([3.0, 4.0]) == pytest.approx(math.sqrt(12.5))
    assert math.isnan(rms([]))


def test_best_fit_frame_undoes_a_rigid_motion():
    stamps = np.arange(0.0, 20.0)
    truth = Trajectory(stamps, [(4 * math.cos(t / 3), 3 * math.sin(t / 2), 0.0) for t in stamps])
    frame = (2.0, -1.0, 0.3)
    seen = truth.transformed(inverse(frame))
    assert best_fit_frame(seen, truth) == pytest.approx(frame)
