"""Planar poses and trajectories: composing frames and comparing an estimate to ground truth.

A pose is (x, y, yaw) in metres and radians. `compose(a, b)` is the pose b expressed in a's
parent frame, i.e. a ∘ b.
"""

import math

import numpy as np


def yaw_of(q):
    """Yaw of a quaternion message (anything with x, y, z, w)."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def compose(a, b):
    ax, ay, ath = a
    bx, by, bth = b
    c, s = math.cos(ath), math.sin(ath)
    return (ax + c * bx - s * by, ay + s * bx + c * by, wrap(ath + bth))


def inverse(a):
    x, y, th = a
    c, s = math.cos(th), math.sin(th)
    return (-c * x - s * y, s * x - c * y, -th)


def wrap(angle):
    return math.atan2(math.sin(angle), math.cos(angle))


class Trajectory:
    """Time-stamped poses, sorted by time."""

    def __init__(self, stamps=(), poses=()):
        order = np.argsort(np.asarray(stamps, dtype=float), kind="stable")
        self.t = np.asarray(stamps, dtype=float)[order]
        self.poses = np.asarray(poses, dtype=float).reshape(-1, 3)[order]

    def __len__(self):
        return len(self.t)

    def at(self, stamp):
        """The latest pose at or before `stamp` (the first pose before the trajectory starts)."""
        i = int(np.searchsorted(self.t, stamp, side="right")) - 1
        return tuple(self.poses[max(i, 0)])

    def length(self):
        steps = np.diff(self.poses[:, :2], axis=0)
        return float(np.hypot(steps[:, 0], steps[:, 1]).sum()) if len(steps) else 0.0

    def transformed(self, frame):
        """This trajectory expressed in the frame whose pose is `frame`."""
        return Trajectory(self.t, [compose(frame, tuple(p)) for p in self.poses])


def chain(outer, inner):
    """outer(t) ∘ inner(t) at inner's stamps, e.g. map→odom ∘ odom→base = map→base."""
    return Trajectory(
        inner.t, [compose(outer.at(t), tuple(p)) for t, p in zip(inner.t, inner.poses, strict=True)]
    )


def position_errors(estimate, truth):
    """Distance between estimate and truth at each of the estimate's stamps."""
    if not len(estimate) or not len(truth):
        return np.zeros(0)
    matched = np.array([truth.at(t)[:2] for t in estimate.t])
    return np.hypot(*(estimate.poses[:, :2] - matched).T)


def rms(errors):
    return float(np.sqrt(np.mean(np.square(errors)))) if len(errors) else float("nan")


def best_fit_frame(estimate, truth):
    """The frame F for which estimate.transformed(F) best fits truth: least-squares positions
    at the estimate's stamps, rotation and translation only (Horn's method), as the standard
    absolute trajectory error (ATE) aligns a trajectory before measuring it."""
    if len(estimate) < 2 or not len(truth):
        return (0.0, 0.0, 0.0)
    src = estimate.poses[:, :2]
    dst = np.array([truth.at(t)[:2] for t in estimate.t])
    ms, md = src.mean(axis=0), dst.mean(axis=0)
    a, b = src - ms, dst - md
    yaw = math.atan2(float(np.sum(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])), float(np.sum(a * b)))
    c, s = math.cos(yaw), math.sin(yaw)
    return (md[0] - (c * ms[0] - s * ms[1]), md[1] - (s * ms[0] + c * ms[1]), yaw)
