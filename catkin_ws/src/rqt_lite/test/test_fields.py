"""rqt_plot's field syntax and value extraction, on plain stand-in message objects."""

import math
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from rqt_lite.fields import (  # noqa: E402
    FieldError,
    Series,
    check_path,
    csv_text,
    extract,
    parse_path,
    split_topic,
)


class Msg:
    """Shaped like a genpy message: __slots__ plus attributes."""

    def __init__(self, **fields):
        self.__slots__ = list(fields)
        for name, value in fields.items():
            setattr(self, name, value)


class Vector3(Msg):
    __slots__ = ["x", "y", "z"]

    def __init__(self, x=0.0, y=0.0, z=0.0):
        self.x, self.y, self.z = x, y, z


class Twist(Msg):
    __slots__ = ["linear", "angular"]

    def __init__(self):
        self.linear, self.angular = Vector3(), Vector3()


class Stamp:
    def __init__(self, secs, nsecs):
        self.secs, self.nsecs = secs, nsecs


TOPICS = ["/cmd_vel", "/cmd_vel_mux/input/teleop", "/scan"]


def test_split_topic_takes_the_longest_published_prefix():
    assert split_topic("cmd_vel/linear/x", TOPICS) == ("/cmd_vel", "linear/x")
    assert split_topic("/cmd_vel_mux/input/teleop/angular/z", TOPICS) == (
        "/cmd_vel_mux/input/teleop",
        "angular/z",
    )
    assert split_topic("scan/ranges[3]", TOPICS) == ("/scan", "ranges[3]")
    assert split_topic("/scan", TOPICS) == ("/scan", "")
    assert split_topic("cmd_velocity/x", TOPICS) is None
    assert split_topic("odom/pose", TOPICS) is None


def test_parse_path():
    assert parse_path("linear/x") == [("linear", None), ("x", None)]
    assert parse_path("ranges[0]") == [("ranges", 0)]
    assert parse_path("points[2]/x") == [("points", 2), ("x", None)]
    assert parse_path("") == []
    for bad in ("linear//x", "a[b]", "1x", "x[0", "a-b"):
        with pytest.raises(FieldError):
            parse_path(bad)


def test_extract_numbers_bools_times_and_indices():
    msg = Twist()
    msg.linear.x, msg.angular.z = 0.5, -1.0
    assert extract(msg, parse_path("linear/x")) == 0.5
    assert extract(msg, parse_path("angular/z")) == -1.0
    arr = Msg(ranges=[1.0, 2.5, 3.0], flag=True, stamp=Stamp(3, 500000000))
    assert extract(arr, parse_path("ranges[1]")) == 2.5
    assert extract(arr, parse_path("ranges[-1]")) == 3.0
    assert extract(arr, parse_path("flag")) == 1.0
    assert extract(arr, parse_path("stamp")) == 3.5
    assert extract(Msg(data=7), []) == 7.0  # std_msgs/Int32-style topic plotted bare


def test_extract_errors_are_clear():
    msg = Twist()
    with pytest.raises(FieldError, match="no field 'w'"):
        extract(msg, parse_path("linear/w"))
    with pytest.raises(FieldError, match="not a number"):
        extract(msg, parse_path("linear"))
    with pytest.raises(FieldError, match=r"ranges\[5\]"):
        extract(Msg(ranges=[1.0]), parse_path("ranges[5]"))


def test_check_path_against_the_type():
    check_path(Twist, parse_path("linear/x"))
    with pytest.raises(FieldError, match="fields: linear, angular"):
        check_path(Twist, parse_path("linar/x"))


def test_series_keeps_gaps_and_csv_lists_samples():
    s = Series("/cmd_vel/linear/x")
    s.add(10.0, 0.5)
    s.add(10.1, math.inf)
    text = csv_text([s], t0=10.0)
    lines = text.splitlines()
    assert lines[0] == "series,time,value"
    assert lines[1] == "/cmd_vel/linear/x,0.000000,0.5"
    assert lines[2].endswith(",nan")


def test_atomic_write_replaces_and_cleans_up(tmp_path):
    from rqt_lite.files import write_atomically, write_text_atomically

    target = tmp_path / "plot.csv"
    write_text_atomically(target, "a\n")
    write_text_atomically(target, "b\n")
    assert target.read_text() == "b\n"
    assert target.stat().st_mode & 0o044  # readable by others, like a normal file

    def fail(tmp):
        Path(tmp).write_text("half")
        raise OSError("disk full")

    with pytest.raises(OSError):
        write_atomically(target, fail)
    assert target.read_text() == "b\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plot.csv"]
