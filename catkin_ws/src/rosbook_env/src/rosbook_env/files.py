"""Checks on files a user names, shared by the nodes that read them."""

import os
import stat


def special_file_note(path):
    """Why `path` must not be read, for a device, FIFO or socket (else None): /dev/zero
    would be read until memory runs out, a FIFO would block forever. A missing file or a
    folder gives None: opening it raises the error the callers already name."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):
        return None
    if stat.S_ISREG(mode) or stat.S_ISDIR(mode):
        return None
    return "not a regular file (a device or a pipe)"
