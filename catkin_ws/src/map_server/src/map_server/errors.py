"""Exceptions for map files: every message starts with the file and says the problem."""


class MapError(Exception):
    """Base class: every message names the file and the problem."""


class MapFileNotFoundError(MapError, FileNotFoundError):
    pass


class MapYamlError(MapError, ValueError):
    pass


class MapImageError(MapError, ValueError):
    pass
