"""Shared bits of the teleop_bot integration tests."""

from pathlib import Path

HERE = Path(__file__).resolve().parent
SEND_KEYS = ["/usr/bin/python3", str(HERE / "send_keys.py")]


def twists(messages):
    """(ros time, linear x, angular z) per recorded Twist."""
    return [(m["ros"], m["msg"]["linear"]["x"], m["msg"]["angular"]["z"]) for m in messages]


def rate_hz(times):
    if len(times) < 2 or times[-1] <= times[0]:
        return 0.0
    return (len(times) - 1) / (times[-1] - times[0])


def values_between(samples, start, end):
    return [(lin, ang) for t, lin, ang in samples if start <= t < end]
