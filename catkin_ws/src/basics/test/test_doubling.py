"""The doubler's arithmetic stays inside std_msgs/Int32 (chapter 3)."""

from basics.doubling import INT32_MAX, INT32_MIN, double_int32


def test_doubles():
    assert double_int32(21) == 42
    assert double_int32(-5) == -10
    assert double_int32(0) == 0


def test_limits():
    assert double_int32(INT32_MAX // 2) == INT32_MAX - 1
    assert double_int32(INT32_MIN // 2) == INT32_MIN
    assert double_int32(INT32_MAX // 2 + 1) is None
    assert double_int32(INT32_MIN // 2 - 1) is None
