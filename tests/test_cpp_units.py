"""Runs every C++ gtest binary the build produced (catkin_add_gtest targets named test_*),
and fails when a test source has no binary: a gtest that was not built must not pass as
"nothing to run"."""

import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
SOURCES = REPO / "catkin_ws" / "src"


def devel_prefix():
    for prefix in os.environ.get("CMAKE_PREFIX_PATH", "").split(":"):
        if (Path(prefix) / ".catkin").exists() and (Path(prefix) / "lib").is_dir():
            return Path(prefix)
    return REPO / "catkin_ws" / "devel"


def expected_gtests():
    """(package, test name) for every C++ test source: catkin_ws/src/PKG/test/test_*.cpp."""
    return sorted(
        (source.parent.parent.name, source.stem)
        for source in SOURCES.glob("*/test/test_*.cpp")
        if "TEST" in source.read_text()
    )


EXPECTED = expected_gtests()


def test_every_cpp_test_source_was_built():
    lib = devel_prefix() / "lib"
    missing = [
        f"{pkg}/{name}" for pkg, name in EXPECTED if not os.access(lib / pkg / name, os.X_OK)
    ]
    assert EXPECTED, "no C++ test sources found under catkin_ws/src/*/test"
    assert not missing, f"gtest binaries not built (run scripts/build.sh): {missing}"


@pytest.mark.parametrize("package,name", EXPECTED, ids=[f"{p}/{n}" for p, n in EXPECTED])
def test_gtest_binary(package, name, tmp_path):
    binary = devel_prefix() / "lib" / package / name
    if not os.access(binary, os.X_OK):
        pytest.fail(f"{binary} was not built (run scripts/build.sh)")
    done = subprocess.run(
        [str(binary), f"--gtest_output=xml:{tmp_path}/result.xml"],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=tmp_path,
        # testing::TempDir() is TEST_TMPDIR: the files a gtest writes there stay in the test's
        # own folder, which pytest prunes, instead of /tmp.
        env=dict(os.environ, TEST_TMPDIR=str(tmp_path)),
    )
    assert done.returncode == 0, done.stdout[-20000:] + done.stderr[-5000:]
    assert "[  PASSED  ]" in done.stdout, done.stdout[-5000:]
