"""The rqt_plot field syntax: `topic/field/subfield`, `topic/array[3]/x`.

Which part is the topic is only known from the master's topic list: the longest published
topic that prefixes the argument wins (`/cmd_vel/linear/x` -> `/cmd_vel`, `linear/x`).
"""

import math
import re

_STEP = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)(?:\[(-?\d+)\])?$")


class FieldError(ValueError):
    pass


def absolute(name):
    return "/" + name.strip("/")


def split_topic(spec, topics):
    """(topic, field path) for `spec`, given the published topic names; None if no match."""
    spec = absolute(spec)
    best = None
    for topic in topics:
        topic = absolute(topic)
        if spec == topic or spec.startswith(topic + "/"):
            if best is None or len(topic) > len(best):
                best = topic
    if best is None:
        return None
    return best, spec[len(best) :].strip("/")


def parse_path(path):
    """'linear/x' -> [('linear', None), ('x', None)]; 'ranges[3]' -> [('ranges', 3)]."""
    if not path:
        return []
    steps = []
    for part in path.split("/"):
        match = _STEP.match(part)
        if not match:
            raise FieldError(f"bad field name {part!r} in {path!r}")
        index = match.group(2)
        steps.append((match.group(1), int(index) if index is not None else None))
    return steps


def to_number(value, what):
    """A plottable float: numbers, bools, and rospy Time/Duration (seconds)."""
    if isinstance(value, bool):
        return float(value)
    if isinstance(value, (int, float)):
        return float(value)
    if hasattr(value, "secs") and hasattr(value, "nsecs"):
        return value.secs + value.nsecs * 1e-9
    raise FieldError(f"{what} is not a number (it is a {type(value).__name__})")


def extract(msg, steps, what="field"):
    """Walk `steps` into a message and return the number there."""
    value = msg
    for name, index in steps:
        if not hasattr(value, name) or name.startswith("_"):
            raise FieldError(f"{what}: no field {name!r}")
        value = getattr(value, name)
        if index is not None:
            try:
                value = value[index]
            except (IndexError, TypeError) as error:
                raise FieldError(f"{what}: {name}[{index}]: {error}") from None
    if not steps and hasattr(value, "__slots__"):
        # A bare topic of a one-number message (std_msgs/Float64 and friends) plots `data`.
        slots = [s for s in value.__slots__ if s != "header"]
        if len(slots) == 1:
            return to_number(getattr(value, slots[0]), what)
    return to_number(value, what)


def check_path(msg_class, steps, what="field"):
    """Fail early on field names the message type does not have (arrays stay unchecked past
    an index, since a default message has empty arrays)."""
    value = msg_class()
    for name, index in steps:
        slots = getattr(value, "__slots__", None)
        if slots is None or name not in slots:
            known = ", ".join(slots or [])
            raise FieldError(f"{what}: no field {name!r} (fields: {known})")
        value = getattr(value, name)
        if index is not None:
            if isinstance(value, (list, tuple)) and len(value) > index >= -len(value):
                value = value[index]
            elif isinstance(value, (list, tuple, bytes)):
                return  # variable array: checked per message
            else:
                raise FieldError(f"{what}: {name} is not an array")


def label(topic, path):
    return topic + ("/" + path if path else "")


class Series:
    """One plotted line: sample times (seconds) and values; non-finite values are kept as NaN
    so the line shows a gap instead of a spike to infinity."""

    def __init__(self, name):
        self.name = name
        self.times = []
        self.values = []

    def add(self, t, value):
        self.times.append(t)
        self.values.append(value if math.isfinite(value) else math.nan)


def csv_text(series_list, t0=0.0):
    lines = ["series,time,value"]
    for series in series_list:
        for t, v in zip(series.times, series.values, strict=True):
            lines.append(f"{series.name},{t - t0:.6f},{v!r}")
    return "\n".join(lines) + "\n"
