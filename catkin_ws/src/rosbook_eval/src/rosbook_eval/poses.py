"""Planar poses and trajectories: composing frames, interpolating, comparing to ground truth.

A pose is (x, y, yaw) in metres and radians. `compose(a, b)` is the pose b expressed in a's
parent frame, i.e. a ∘ b.

One interpolation for every track (ground truth, odometry, SLAM's map→odom correction):
linear between the two samples around a stamp, the yaw along the shorter arc, clamped to
the first and last sample outside the track's span. Errors are only measured at stamps
inside the truth's span, so clamping never invents a truth the bag does not hold.
"""

import math

import numpy as np


def wrap(angle):
    return math.atan2(math.sin(angle), math.cos(angle))


def compose(a, b):
    ax, ay, ath = a
    bx, by, bth = b
    c, s = math.cos(ath), math.sin(ath)
    return (ax + c * bx - s * by, ay + s * bx + c * by, wrap(ath + bth))


def inverse(a):
    x, y, th = a
    c, s = math.cos(th), math.sin(th)
    return (-c * x - s * y, s * x - c * y, -th)


class Trajectory:
    """Time-stamped poses, sorted by time."""

    def __init__(self, stamps=(), poses=()):
        order = np.argsort(np.asarray(stamps, dtype=float), kind="stable")
        self.t = np.asarray(stamps, dtype=float)[order]
        self.poses = np.asarray(poses, dtype=float).reshape(-1, 3)[order]

    @classmethod
    def from_rows(cls, rows):
        """From (t, x, y, yaw) rows, as slam_offline's --trajectory CSV holds them."""
        rows = np.asarray(rows, dtype=float).reshape(-1, 4)
        return cls(rows[:, 0], rows[:, 1:])

    def __len__(self):
        return len(self.t)

    def at_many(self, stamps):
        """Poses (N x 3) linearly interpolated at `stamps`, the yaw along the shorter arc;
        clamped to the first and last pose outside the trajectory's span."""
        stamps = np.asarray(stamps, dtype=float).reshape(-1)
        if not len(self):
            raise ValueError("an empty trajectory has no pose")
        if len(self) == 1:
            return np.repeat(self.poses[:1], len(stamps), axis=0)
        # Unwrapped, np.interp between neighbours turns through the shorter arc.
        yaw = np.unwrap(self.poses[:, 2])
        out = np.column_stack(
            [
                np.interp(stamps, self.t, self.poses[:, 0]),
                np.interp(stamps, self.t, self.poses[:, 1]),
                np.interp(stamps, self.t, yaw),
            ]
        )
        out[:, 2] = np.arctan2(np.sin(out[:, 2]), np.cos(out[:, 2]))
        return out

    def at(self, stamp):
        return tuple(float(v) for v in self.at_many([stamp])[0])

    def covers(self, stamps):
        """Which of `stamps` lie within this trajectory's span (no extrapolation needed)."""
        stamps = np.asarray(stamps, dtype=float)
        if not len(self):
            return np.zeros(stamps.shape, dtype=bool)
        return (stamps >= self.t[0]) & (stamps <= self.t[-1])

    def select(self, mask):
        return Trajectory(self.t[mask], self.poses[mask])

    def length(self):
        steps = np.diff(self.poses[:, :2], axis=0)
        return float(np.hypot(steps[:, 0], steps[:, 1]).sum()) if len(steps) else 0.0

    def transformed(self, frame):
        """This trajectory expressed in the frame whose pose is `frame`."""
        return Trajectory(self.t, [compose(frame, tuple(p)) for p in self.poses])

    def resampled(self, stamps):
        return Trajectory(stamps, self.at_many(stamps))


def chain(outer, inner):
    """outer(t) ∘ inner(t) at inner's stamps from outer's first one on, e.g. map→odom ∘
    odom→base = map→base. Stamps before `outer` starts are dropped (no correction yet)."""
    inner = inner.select(np.asarray(inner.t) >= outer.t[0]) if len(outer) else Trajectory()
    outer_poses = outer.at_many(inner.t) if len(inner) else np.zeros((0, 3))
    return Trajectory(
        inner.t,
        [compose(tuple(o), tuple(p)) for o, p in zip(outer_poses, inner.poses, strict=True)],
    )


def position_errors(estimate, truth):
    """Distance between estimate and the interpolated truth at each of the estimate's stamps
    (the caller keeps them inside the truth's span)."""
    if not len(estimate) or not len(truth):
        return np.zeros(0)
    return np.hypot(*(estimate.poses[:, :2] - truth.at_many(estimate.t)[:, :2]).T)


def rms(errors):
    return float(np.sqrt(np.mean(np.square(errors)))) if len(errors) else float("nan")


def best_fit_frame(estimate, truth):
    """The frame F for which estimate.transformed(F) best fits truth: least-squares positions
    at the estimate's stamps, rotation and translation only (Horn's method), as the standard
    absolute trajectory error (ATE) aligns a trajectory before measuring it."""
    if len(estimate) < 2 or not len(truth):
        raise ValueError("need two poses within the ground truth's time span to fit a frame")
    src = estimate.poses[:, :2]
    dst = truth.at_many(estimate.t)[:, :2]
    ms, md = src.mean(axis=0), dst.mean(axis=0)
    a, b = src - ms, dst - md
    yaw = math.atan2(float(np.sum(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])), float(np.sum(a * b)))
    c, s = math.cos(yaw), math.sin(yaw)
    return (md[0] - (c * ms[0] - s * ms[1]), md[1] - (s * ms[0] + c * ms[1]), yaw)


def start_frame(estimate, truth):
    """The frame F that puts the estimate's first pose on the true pose at that stamp: the
    placement by the true start pose. No fitting, so an early heading error turns the whole
    trajectory (and the map with it) and counts everywhere."""
    t0 = estimate.t[0]
    return compose(truth.at(t0), inverse(tuple(estimate.poses[0])))
