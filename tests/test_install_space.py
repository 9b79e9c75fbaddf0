"""`catkin_make install` (run by scripts/build.sh) gives a working install space: sourcing
catkin_ws/install/setup.bash alone, the simulator, slam_gmapping, map_server and map_saver run,
score_slam scores a bag recorded there with the Turtlebot tuning, make_worlds.py writes worlds
(into the current folder by default), and nothing in it points back into the source tree or
the devel space."""

import json
import math
import os
import subprocess
from pathlib import Path

import pytest
from roskit import RosGraph

REPO = Path(__file__).resolve().parent.parent
INSTALL = REPO / "catkin_ws" / "install"


@pytest.fixture(scope="module")
def install_env():
    setup = INSTALL / "setup.bash"
    assert setup.exists(), f"{setup} missing: run scripts/build.sh (it runs catkin_make install)"
    # A user's shell: a pyenv python3 may come first, and no ROS variables are set.
    keep = {k: v for k, v in os.environ.items() if not k.startswith(("ROS", "CMAKE", "PYTHON"))}
    keep["PATH"] = "/root/.pyenv/shims:/usr/local/bin:/usr/bin:/bin"
    keep.pop("LD_LIBRARY_PATH", None)
    keep.pop("PKG_CONFIG_PATH", None)
    done = subprocess.run(
        ["bash", "-c", f"source '{setup}' && env -0"],
        env=keep,
        capture_output=True,
        check=True,
        cwd="/",
    )
    env = dict(item.split("=", 1) for item in done.stdout.decode().split("\0") if "=" in item)
    assert "catkin_ws/devel" not in env.get("ROS_PACKAGE_PATH", ""), env["ROS_PACKAGE_PATH"]
    return env


@pytest.fixture
def ros_installed(tmp_path, install_env):
    graph = RosGraph(tmp_path, base_env=install_env)
    try:
        yield graph
    finally:
        graph.close()


def test_no_installed_script_or_file_points_into_the_source_tree_or_devel_space():
    source, devel = str(REPO / "catkin_ws" / "src"), str(REPO / "catkin_ws" / "devel")
    offenders = []
    for path in INSTALL.rglob("*"):
        # Byte-code caches name the file they were compiled from; they are not installed.
        if path.is_file() and not path.is_symlink() and path.suffix != ".pyc":
            data = path.read_bytes()
            if b"\0" in data:
                continue  # a binary names its sources in log macros (__FILE__), never opens them
            if source.encode() in data or devel.encode() in data:
                offenders.append(str(path.relative_to(INSTALL)))
    assert not offenders, offenders


def test_packages_and_python_resolve_to_the_install_space(ros_installed):
    for package in ("bullet_turtlebot", "gmapping_lite", "map_server", "rosbook_demo", "gmapping"):
        found = ros_installed.run(["rospack", "find", package]).stdout.strip()
        assert found.startswith(str(INSTALL)), (package, found)
    python = ros_installed.run(["python3", "-c", "import rospy, sys; print(sys.executable)"])
    assert os.path.samefile(python.stdout.strip(), "/usr/bin/python3")


@pytest.mark.timeout(400)
def test_simulator_slam_map_saver_and_map_server_from_the_install_space(ros_installed, tmp_path):
    ros = ros_installed
    ros.start(["roslaunch", "bullet_turtlebot", "simulator.launch", "world:=maze", "speed:=2"])
    scan = ros.echo("/scan", count=1, timeout=90)[0]["msg"]
    assert len(scan["ranges"]) == 640
    ros.start(["rosrun", "gmapping", "slam_gmapping", "_map_update_interval:=1.0"])
    grid = ros.echo("/map", count=1, timeout=120)[0]["msg"]
    assert grid["info"]["resolution"] == pytest.approx(0.05)
    assert sum(1 for v in grid["data"] if v == 100) > 20  # the maze's walls near the start
    saved = ros.run(
        ["rosrun", "map_server", "map_saver", "-f", str(tmp_path / "made")], timeout=120
    )
    assert (tmp_path / "made.pgm").stat().st_size > 0, saved.stdout
    truth = ros.run(
        ["rosrun", "bullet_turtlebot", "world_to_map", "maze", "-f", str(tmp_path / "t")]
    )
    assert (tmp_path / "t.yaml").exists(), truth.stdout
    # Serve the map just saved, as chapter 9 does, in the served namespace.
    ros.start(["rosrun", "map_server", "map_server", str(tmp_path / "made.yaml"), "map:=served"])
    served = ros.echo("/served", count=1, timeout=60)[0]["msg"]
    assert served["info"]["width"] > 0 and served["info"]["height"] > 0


def test_make_worlds_writes_into_the_current_folder_by_default(ros_installed, tmp_path):
    done = ros_installed.run(["rosrun", "bullet_turtlebot", "make_worlds.py"], cwd=tmp_path)
    assert f"to {tmp_path}" in done.stdout, done.stdout
    for world in ("playground", "maze", "office", "hospital", "warehouse", "ring", "lab"):
        assert (tmp_path / f"{world}.yaml").exists() and (tmp_path / f"{world}.pgm").exists()
    family = tmp_path / "family"
    ros_installed.run(
        ["rosrun", "bullet_turtlebot", "make_worlds.py", "--family", "ring"]
        + ["--seed", "2", str(family)]
    )
    assert (family / "ring_2.yaml").exists()


@pytest.mark.timeout(500)
def test_score_slam_runs_slam_offline_with_the_turtlebot_tuning(ros_installed, tmp_path):
    """A short drive in the office recorded from the install space, scored by score_slam's
    default path: slam_offline over the bag with the Turtlebot tuning (config/turtlebot.yaml,
    found through the package, not next to the script)."""
    ros = ros_installed
    usage = ros.run(["rosrun", "gmapping_lite", "score_slam", "--help"]).stdout
    assert "config/turtlebot.yaml" in usage, usage
    ros.start(["roslaunch", "bullet_turtlebot", "simulator.launch", "world:=office", "speed:=4"])
    ros.wait_for_topic("/scan", timeout=90)
    bag = tmp_path / "drive.bag"
    topics = ["/scan", "/tf", "/tf_static", "/odom", "/base_pose_ground_truth"]
    recorder = ros.start(["rosbag", "record", "-O", str(bag), *topics])

    def subscribed():
        subscribers = dict(ros.system_state()[1])
        return all(any("record" in n for n in subscribers.get(t, [])) for t in topics)

    ros.wait_for(subscribed, 60, "rosbag record to subscribe")
    driver = ros.start(["rosrun", "gmapping_lite", "waypoint_driver", "--route", "corridor"])
    driver.wait(timeout=300)
    assert driver.returncode == 0, ros.output(driver)
    ros.stop(recorder)
    ros.wait_for(bag.exists, 60, "the bag to be closed")
    done = ros.run(
        ["rosrun", "gmapping_lite", "score_slam", str(bag), "--world", "office", "--json"],
        timeout=300,
    )
    figures = json.loads(done.stdout.strip().splitlines()[-1])
    # The corridor route's updates (linearUpdate 0.5 m, angularUpdate 0.436 rad: the tuning's).
    assert figures["poses"] >= 5, figures
    assert math.isfinite(figures["slam_rms"]) and 0 < figures["near_wall_fraction"] <= 1
