"""Acceleration-limited velocity steps (keys_to_twist_with_ramps)."""

import math


def ramped_vel(v_prev, v_target, dt, accel):
    """Step from v_prev towards v_target by at most accel * dt.

    A non-positive or non-finite dt (a clock jump, e.g. a sim-time reset) gives no step.
    """
    if not math.isfinite(dt) or dt <= 0.0:
        return v_prev
    step = accel * dt
    error = v_target - v_prev
    if abs(error) <= step:
        return v_target
    return v_prev + math.copysign(step, error)


def ramped_twist(prev, target, dt, linear_accel, angular_accel):
    """(linear, angular) pairs: each component ramped with its own acceleration."""
    return (
        ramped_vel(prev[0], target[0], dt, linear_accel),
        ramped_vel(prev[1], target[1], dt, angular_accel),
    )
