"""Runs every C++ gtest binary the build produced (catkin_add_gtest targets named test_*)."""

import os
import subprocess
from pathlib import Path

import pytest


def devel_prefix():
    for prefix in os.environ.get("CMAKE_PREFIX_PATH", "").split(":"):
        if (Path(prefix) / ".catkin").exists():
            return Path(prefix)
    return Path(__file__).resolve().parent.parent / "catkin_ws" / "devel"


GTESTS = sorted(p for p in (devel_prefix() / "lib").glob("*/test_*") if os.access(p, os.X_OK))


@pytest.mark.parametrize(
    "binary", GTESTS, ids=lambda p: f"{p.parent.name}/{p.name}" if isinstance(p, Path) else str(p)
)
def test_gtest_binary(binary, tmp_path):
    done = subprocess.run(
        [str(binary), f"--gtest_output=xml:{tmp_path}/result.xml"],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=tmp_path,
    )
    assert done.returncode == 0, done.stdout[-20000:] + done.stderr[-5000:]
