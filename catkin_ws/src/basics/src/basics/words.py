"""Word counting for the WordCount service (chapter 4) and the book's ways of returning it."""

# The service callback may return the response object, the bare value, a list or tuple of
# the response fields in order, or a dict keyed by field name; rospy turns each into a
# WordCountResponse.
RETURN_MODES = ("response", "value", "list", "tuple", "dict")


def count_words(text):
    """Number of whitespace-separated words, as the book's len(words.split())."""
    return len(text.split())


def shape_reply(count, mode, response_type):
    """Return `count` in the style `mode` (one of RETURN_MODES)."""
    if mode == "response":
        return response_type(count)
    if mode == "value":
        return count
    if mode == "list":
        return [count]
    if mode == "tuple":
        return (count,)
    if mode == "dict":
        return {"count": count}
    raise ValueError(f"unknown return mode {mode!r}; choose one of: {', '.join(RETURN_MODES)}")


def format_count(words, count):
    """The client's printout: `these are some words -> 4`."""
    return f"{words} -> {count}"
