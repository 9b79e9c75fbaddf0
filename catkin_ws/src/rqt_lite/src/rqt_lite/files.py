"""Atomic file writes: a reader never sees half a plot or half a graph."""

import os
import tempfile
from pathlib import Path


def write_atomically(path, write):
    """Call write(tmp_path) for a temporary file next to `path`, then rename it over `path`."""
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    fd, tmp = tempfile.mkstemp(prefix="." + path.stem + "-", suffix=path.suffix, dir=directory)
    os.close(fd)
    try:
        write(tmp)
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; give the usual mode
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_text_atomically(path, text):
    write_atomically(path, lambda tmp: Path(tmp).write_text(text))


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask
