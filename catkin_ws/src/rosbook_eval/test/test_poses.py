import math

import numpy as np
import pytest
from rosbook_eval.poses import (
    Trajectory,
    best_fit_frame,
    chain,
    compose,
    inverse,
    position_errors,
    rms,
    start_frame,
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


def test_at_interpolates_linearly_and_clamps_at_the_ends():
    traj = Trajectory([2.0, 1.0, 3.0], [(2, 0, 0), (1, 0, 0), (3, 4, 0)])
    assert traj.at(0.5) == pytest.approx((1, 0, 0))  # before the start: the first pose
    assert traj.at(2.5) == pytest.approx((2.5, 2.0, 0))
    assert traj.at(9.0) == pytest.approx((3, 4, 0))


def test_yaw_is_interpolated_along_the_shorter_arc():
    traj = Trajectory([0.0, 1.0], [(0, 0, math.pi - 0.1), (0, 0, -math.pi + 0.1)])
    assert abs(wrap(traj.at(0.5)[2] - math.pi)) == pytest.approx(0.0, abs=1e-9)
    assert traj.at(0.25)[2] == pytest.approx(math.pi - 0.05)


def test_covers_is_the_span():
    traj = Trajectory([1.0, 2.0], [(0, 0, 0), (1, 0, 0)])
    assert list(traj.covers([0.5, 1.0, 1.5, 2.0, 2.5])) == [False, True, True, True, False]


def test_length_sums_steps():
    traj = Trajectory([0, 1, 2], [(0, 0, 0), (3, 4, 0), (3, 0, 0)])
    assert traj.length() == pytest.approx(9.0)


def test_chain_interpolates_the_correction_and_drops_stamps_before_it():
    correction = Trajectory([1.0, 5.0], [(0, 0, 0), (1.0, 0, 0)])
    odom = Trajectory([0.0, 3.0, 6.0], [(0, 0, 0), (0, 0, 0), (0, 0, 0)])
    chained = chain(correction, odom)
    assert list(chained.t) == [3.0, 6.0]
    assert [p[0] for p in chained.poses] == pytest.approx([0.5, 1.0])


def test_position_errors_against_the_interpolated_truth_and_rms():
    truth = Trajectory([0, 2], [(0, 0, 0), (2, 0, 0)])
    estimate = Trajectory([0, 1], [(0, 3, 0), (1, 4, 0)])
    assert list(position_errors(estimate, truth)) == pytest.approx([3.0, 4.0])
    assert rms([3.0, 4.0]) == pytest.approx(math.sqrt(12.5))
    assert math.isnan(rms([]))


def test_best_fit_frame_undoes_a_rigid_motion():
    stamps = np.arange(0.0, 20.0)
    truth = Trajectory(stamps, [(4 * math.cos(t / 3), 3 * math.sin(t / 2), 0.0) for t in stamps])
    frame = (2.0, -1.0, 0.3)
    seen = truth.transformed(inverse(frame))
    assert best_fit_frame(seen, truth) == pytest.approx(frame)
    assert rms(position_errors(seen.transformed(frame), truth)) == pytest.approx(0.0, abs=1e-9)


def test_best_fit_needs_two_poses():
    with pytest.raises(ValueError, match="two poses"):
        best_fit_frame(Trajectory([0.0], [(0, 0, 0)]), Trajectory([0.0], [(0, 0, 0)]))


def test_start_frame_puts_the_first_pose_on_the_truth():
    truth = Trajectory([0.0, 1.0], [(5.0, 1.0, math.pi / 2), (5.0, 2.0, math.pi / 2)])
    odom = Trajectory([0.0, 1.0], [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0)])
    frame = start_frame(odom, truth)
    assert frame == pytest.approx((5.0, 1.0, math.pi / 2))
    assert odom.transformed(frame).poses[1] == pytest.approx((5.0, 2.0, math.pi / 2))
