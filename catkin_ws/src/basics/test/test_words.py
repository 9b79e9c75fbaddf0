"""Word counting and the service callback's return styles (chapter 4)."""

import pytest
from basics.words import RETURN_MODES, count_words, format_count, shape_reply


class FakeResponse:
    def __init__(self, count):
        self.count = count


@pytest.mark.parametrize(
    "text, expected",
    [
        ("one two three", 3),
        ("these are some words", 4),
        ("", 0),
        ("   ", 0),
        ("  leading and  doubled   spaces ", 4),
        ("tabs\tand\nnewlines", 3),
        ("unicode wörds ünd ñ", 4),
    ],
)
def test_count_words(text, expected):
    assert count_words(text) == expected


def test_count_words_very_long_string():
    assert count_words("word " * 1_000_000) == 1_000_000


def test_every_mode_carries_the_count():
    shaped = {mode: shape_reply(7, mode, FakeResponse) for mode in RETURN_MODES}
    assert shaped["response"].count == 7
    assert shaped["value"] == 7
    assert shaped["list"] == [7]
    assert shaped["tuple"] == (7,)
    assert shaped["dict"] == {"count": 7}


def test_unknown_mode_is_refused_by_name():
    with pytest.raises(ValueError, match="unknown return mode 'xml'.*response, value"):
        shape_reply(1, "xml", FakeResponse)


def test_format_count_matches_the_book():
    assert format_count("these are some words", 4) == "these are some words -> 4"
