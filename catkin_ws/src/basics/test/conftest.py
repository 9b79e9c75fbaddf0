"""Unit tests of the ROS-free helpers: import them from the sourced devel space, or from the
source tree when no workspace is sourced (appended, so a sourced devel space wins)."""

import sys
from pathlib import Path

sys.path.append(str(Path(__file__).resolve().parent.parent / "src"))
