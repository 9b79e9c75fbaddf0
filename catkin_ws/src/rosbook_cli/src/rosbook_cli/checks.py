"""Boundary checks for command-line tools: each turns a bad argument or a missing master into
one line that names the bad value and the fix, before any long work starts.

argparse types (`finite_float`, `positive_float`, `non_negative_float`) make argparse print
`PROG: error: argument --x: ...` and exit 2; the other checks exit 1 with `PROG: ...`."""

import argparse
import math
import os
import sys
from pathlib import Path


def finite_float(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"{text!r} is not a finite number")
    return value


def positive_float(text):
    value = finite_float(text)
    if value <= 0:
        raise argparse.ArgumentTypeError(f"{text!r} must be greater than 0")
    return value


def non_negative_float(text):
    value = finite_float(text)
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text!r} must be 0 or more")
    return value


def require_master(prog):
    """Exit 1 with the fix when no ROS master answers (rospy would retry forever)."""
    import rosgraph

    if not rosgraph.is_master_online():
        uri = rosgraph.get_master_uri()
        sys.exit(f"{prog}: cannot reach the ROS master at {uri}: start `roscore` first")


def output_folder_problem(path):
    """Why files cannot be written at `path` (None when they can): its folder is missing or
    not writable, or the path is a folder itself."""
    path = Path(path)
    if str(path) == "" or path.name == "":
        return f"{str(path)!r} is not a file name"
    if path.is_dir():
        return f"{path} is a folder; give a file name inside it"
    folder = path.parent
    if not folder.is_dir():
        return f"folder {folder} does not exist (create it with: mkdir -p '{folder}')"
    if not os.access(folder, os.W_OK | os.X_OK):
        return f"folder {folder} is not writable"
    return None


def require_output(prog, path):
    """Exit 1 before the work starts when `path` cannot be written."""
    problem = output_folder_problem(path)
    if problem:
        sys.exit(f"{prog}: cannot write {path}: {problem}")


def require_output_folder(prog, folder):
    """Create `folder` (and parents) for outputs, or exit 1 saying why it cannot be used."""
    folder = Path(folder)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        sys.exit(f"{prog}: cannot create the output folder {folder}: {err.strerror or err}")
    if not os.access(folder, os.W_OK | os.X_OK):
        sys.exit(f"{prog}: the output folder {folder} is not writable")
