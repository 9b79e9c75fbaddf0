"""Write several files so that each is either the complete new version or the old one.

Every file is first written and fsynced to a temporary file in its own directory; only
when all of them are complete are they renamed over their targets. A failure while
writing leaves the old files untouched and removes the temporary files.
"""

import os
import tempfile
from pathlib import Path


def write_files_atomically(contents):
    """contents: {path: bytes}. Returns the list of paths written, in order."""
    staged = []
    try:
        for path, data in contents.items():
            path = Path(path)
            directory = path.parent if str(path.parent) else Path(".")
            if not directory.is_dir():
                raise FileNotFoundError(f"cannot write {path}: no directory {directory}")
            try:
                fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=directory)
            except OSError as err:  # name the file the user asked for, not the temporary one
                raise type(err)(err.errno, f"cannot write {path}: {err.strerror}") from None
            staged.append((tmp, path))
            with os.fdopen(fd, "wb") as handle:
                handle.write(data)
                handle.flush()
                os.fsync(handle.fileno())
            os.chmod(tmp, 0o644)
        for tmp, path in staged:
            os.replace(tmp, path)
        _sync_directories({path.parent for _, path in staged})
    except BaseException:
        for tmp, _ in staged:
            try:
                os.unlink(tmp)
            except FileNotFoundError:
                pass
        raise
    return [path for _, path in staged]


def _sync_directories(directories):
    # The renames are durable only once the directory entries are on disk.
    for directory in directories:
        try:
            fd = os.open(directory or ".", os.O_RDONLY)
        except OSError:
            continue
        try:
            os.fsync(fd)
        except OSError:
            pass
        finally:
            os.close(fd)
