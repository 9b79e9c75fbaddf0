"""cbreak mode on a real pseudo-terminal: keys arrive one by one, the terminal comes back."""

import os
import sys
import termios
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from teleop_bot.terminal import KeyReader, NotATerminal, cbreak_terminal  # noqa: E402


@pytest.fixture
def pty_pair():
    master, slave = os.openpty()
    yield master, slave
    os.close(master)
    os.close(slave)


def test_cbreak_reads_keys_without_enter_and_restores(pty_pair):
    master, slave = pty_pair
    before = termios.tcgetattr(slave)
    with cbreak_terminal(slave):
        assert not termios.tcgetattr(slave)[3] & termios.ICANON
        os.write(master, "wé".encode())
        reader = KeyReader(slave)
        assert reader.read(1.0) == "wé"
        assert reader.read(0.05) == ""
    assert termios.tcgetattr(slave) == before


def test_restored_after_an_exception(pty_pair):
    _, slave = pty_pair
    before = termios.tcgetattr(slave)
    with pytest.raises(KeyboardInterrupt), cbreak_terminal(slave):
        raise KeyboardInterrupt
    assert termios.tcgetattr(slave) == before


def test_not_a_terminal(tmp_path):
    with open(tmp_path / "f", "w") as f, pytest.raises(NotATerminal, match="not a terminal"):
        with cbreak_terminal(f.fileno()):
            pass


def test_split_utf8_sequence(pty_pair):
    master, slave = pty_pair
    with cbreak_terminal(slave):
        reader = KeyReader(slave)
        data = "é".encode()
        os.write(master, data[:1])
        assert reader.read(1.0) == ""
        os.write(master, data[1:])
        assert reader.read(1.0) == "é"
