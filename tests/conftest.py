"""Shared fixtures: `ros` gives each test its own roscore on a free port. Also the quick tier."""

import os
import sys
import tempfile
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from roskit import SHARED_ROSRUN_ANSWERS, RosGraph  # noqa: E402

if SHARED_ROSRUN_ANSWERS not in os.environ:  # the controller: its workers inherit the folder
    _rosrun_answers = tempfile.TemporaryDirectory(prefix="roskit-rosrun-")
    os.environ[SHARED_ROSRUN_ANSWERS] = _rosrun_answers.name

# The tests are headless: the simulator launch files open rviz where $DISPLAY is set. Tests
# that need a window make their own display (xvfb-run) and set it for what they start.
os.environ.pop("DISPLAY", None)


@pytest.fixture
def ros(tmp_path):
    graph = RosGraph(tmp_path)
    try:
        yield graph
    finally:
        graph.close()


# -- the quick tier (`make test-fast`) ---------------------------------------------------------
# For the edit-test loop: every unit test (no ROS master), every gtest, and these integration
# tests, one or two per package, none simulating more than 30 sim s. ROSBOOK_TIER=fast selects
# them; a name here that matches no test fails the run, so the list cannot rot silently.
FAST_INTEGRATION = (
    "tests/test_workspace.py",
    "tests/test_book_aliases.py::test_rosrun_rospy_tutorials_talker_and_listener",
    "tests/basics/test_services.py::test_word_count_from_rosservice_and_service_client",
    "tests/basics/test_messages.py",
    "tests/bullet_turtlebot/test_simulator_launch.py::test_turtlebot_in_stage_launch_brings_up_the_maze",
    "tests/map_server/test_map_server.py::test_books_command_from_maps_folder",
    "tests/launch/test_launch_files.py::test_the_table_names_every_launch_file",
    "tests/rosbook_eval/test_same_figures.py",
    "tests/bench/test_results_section.py",  # unit tests on text (bench/ has no test folder)
    "tests/bench/test_bench_chapter9.py",  # unit tests of its tour (no ROS)
    "tests/launch/test_launch_files.py::test_launch_file_brings_up_its_nodes[catkin_ws/src/rosbook_demo/launch/mapping_live.launch]",
)


def _is_fast(nodeid):
    if nodeid.startswith("catkin_ws/src/") or nodeid.startswith("tests/test_cpp_units.py"):
        return True
    return any(_is_fast_match(nodeid, name) for name in FAST_INTEGRATION)


def pytest_collection_modifyitems(config, items):
    if os.environ.get("ROSBOOK_TIER") == "fast":
        _keep_fast(config, items)
    _long_modules_first(items)


def _keep_fast(config, items):
    unmatched = [
        name for name in FAST_INTEGRATION if not any(_is_fast_match(i.nodeid, name) for i in items)
    ]
    if unmatched:
        raise pytest.UsageError(f"FAST_INTEGRATION names no collected test: {unmatched}")
    keep = [item for item in items if _is_fast(item.nodeid)]
    config.hook.pytest_deselected(items=[item for item in items if not _is_fast(item.nodeid)])
    items[:] = keep


def _is_fast_match(nodeid, name):
    return nodeid == name or nodeid.startswith(name + "::")


# -- order ----------------------------------------------------------------------------------
# scripts/test.sh runs pytest-xdist with `--dist loadscope`: a whole module goes to one worker
# (so a module's shared roscore or main-job run is set up once), and an idle worker takes the
# next module in collection order. Ordered longest first by the module's recorded total
# (tests/durations.txt, see tests/tools/record_durations.py), that is greedy
# longest-processing-time scheduling, which ends within a third of the best possible
# finish. (Plain `--dist load` hands out runs of consecutive tests: one worker got every long
# module and ran for minutes after the others had finished.) Modules the file does not name
# go last; a stale file only costs time.
DURATIONS = Path(__file__).resolve().parent / "durations.txt"


def _recorded_durations():
    if not DURATIONS.exists():
        return {}
    found = {}
    for line in DURATIONS.read_text().splitlines():
        seconds, _, nodeid = line.partition(" ")
        if seconds and not seconds.startswith("#"):
            found[nodeid.strip()] = float(seconds)
    return found


def _long_modules_first(items):
    recorded = _recorded_durations()
    total = {}
    for item in items:
        module = item.nodeid.split("::", 1)[0]
        total[module] = total.get(module, 0.0) + recorded.get(item.nodeid, 0.0)
    items.sort(key=lambda item: -total[item.nodeid.split("::", 1)[0]])
