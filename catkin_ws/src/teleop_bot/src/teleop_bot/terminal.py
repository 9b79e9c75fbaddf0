"""Reading single keystrokes from a terminal, and always giving the terminal back.

The book's key_publisher puts the terminal in cbreak mode and restores it only when its loop
ends normally, so Ctrl-C or an exception leaves the shell without echo. Here the restore
sits in a `finally`.
"""

import codecs
import contextlib
import os
import select
import termios
import tty


class NotATerminal(RuntimeError):
    pass


@contextlib.contextmanager
def cbreak_terminal(fd):
    """Put terminal `fd` in cbreak mode (keys arrive at once, no echo; Ctrl-C still raises
    SIGINT) for the duration of the block; restore the saved attributes however it ends."""
    if not os.isatty(fd):
        raise NotATerminal(
            "standard input is not a terminal: run this node in a terminal window "
            '(from roslaunch use output="screen" and keep roslaunch in the foreground)'
        )
    saved = termios.tcgetattr(fd)
    try:
        tty.setcbreak(fd, termios.TCSANOW)
        yield
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, saved)


class KeyReader:
    """Non-blocking reads of whole characters (UTF-8 may span several bytes)."""

    def __init__(self, fd):
        self.fd = fd
        self.decoder = codecs.getincrementaldecoder("utf-8")(errors="replace")

    def read(self, timeout):
        """Characters typed so far, waiting up to `timeout` seconds for the first one.

        Returns "" on timeout; raises EOFError when the terminal is gone.
        """
        ready, _, _ = select.select([self.fd], [], [], timeout)
        if not ready:
            return ""
        data = os.read(self.fd, 64)
        if not data:
            raise EOFError("terminal closed")
        return self.decoder.decode(data)
