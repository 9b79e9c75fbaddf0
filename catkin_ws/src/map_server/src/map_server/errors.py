"""Exceptions for map files: every message starts with the file and says the problem."""

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
