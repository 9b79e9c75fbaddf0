"""The doubler's arithmetic (chapter 3), kept inside std_msgs/Int32's range."""

INT32_MIN = -(2**31)
INT32_MAX = 2**31 - 1


def double_int32(value):
    """2 * value, or None when the result does not fit in an Int32."""
    doubled = 2 * value
    if not INT32_MIN <= doubled <= INT32_MAX:
        return None
    return doubled
