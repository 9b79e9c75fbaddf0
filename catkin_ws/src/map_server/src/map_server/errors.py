"""Exceptions for map files: every message starts with the file and says the problem."""

import os
import stat
from pathlib import Path


class MapError(Exception):
    """Base class: every message names the file and the problem."""


class MapFileNotFoundError(MapError, FileNotFoundError):
    pass


class MapYamlError(MapError, ValueError):
    pass


class MapImageError(MapError, ValueError):
    pass


def cwd_note(path):
    """For a relative path, where it was looked for."""
    return "" if Path(path).is_absolute() else f" (looked in {Path.cwd()})"


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
