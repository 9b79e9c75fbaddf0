"""The end-to-end explorer runs' shared start: the simulator, SLAM (or the stand-in mapper
on perfect odometry) and the explorer launched paused on a world, the coverage recorder
scoring against the world's own map, then the simulator unpaused."""

import os
import subprocess
from pathlib import Path

from kinematic_sim import WORLDS
from roskit import read_jsonl

HERE = Path(__file__).resolve().parent
PYTHON = "/usr/bin/python3"


def slam_node_available():
    """gmapping_lite's slam_gmapping built in the sourced workspace?"""
    done = subprocess.run(["rospack", "find", "gmapping_lite"], capture_output=True, text=True)
    if done.returncode != 0:
        return False
    for prefix in os.environ.get("CMAKE_PREFIX_PATH", "").split(":"):
        if prefix and (Path(prefix) / "lib" / "gmapping_lite" / "slam_gmapping").exists():
            return True
    return False


def start_exploration(ros, tmp_path, world, speed, use_slam, save_map=None):
    """Launch everything paused on `world` (a name or a world file), start the coverage
    recorder, unpause; return the path of the recorder's JSON lines (one each 10 s sim)."""
    # Here, not at the top: a workspace without bullet_turtlebot skips these tests.
    from bullet_turtlebot.world_start import start_pose

    truth = tmp_path / "truth"
    ros.run(["rosrun", "bullet_turtlebot", "world_to_map", str(world), "-f", str(truth)])
    # explore_sim.launch's simulator waits for a lagging driver (wait_for_commands 0.3).
    common = [f"world:={world}", f"speed:={speed}", "seed:=1", "start_paused:=true"]
    # Before any node starts: rospy reads /use_sim_time once, in init_node, and a node
    # started beside the launch that sets it could otherwise come up first on wall time.
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    if use_slam:
        ros.start(["roslaunch", "explorer", "explore_sim.launch", *common], name="explore_sim")
    else:
        # Stand-in for SLAM: perfect odometry, identity map -> odom, a scan-to-grid mapper.
        ros.start(
            ["roslaunch", "bullet_turtlebot", "simulator.launch", "odom_noise:=false", *common],
            name="sim",
        )
        ros.start([PYTHON, str(HERE / "stand_in_mapper.py")], name="stand_in_mapper")
        ros.start(["roslaunch", "explorer", "explore.launch"], name="explorer")
    ros.wait_for_service("simulator/unpause", timeout=90)
    ros.wait_for_topic("explorer/done", timeout=60)
    out = tmp_path / "coverage.jsonl"
    recorder = [PYTHON, str(HERE / "coverage_recorder.py"), "--truth", f"{truth}.yaml"]
    recorder += ["--start", *map(str, start_pose(str(world), WORLDS)), "--out", str(out)]
    recorder += ["--period", "10"]
    if save_map is not None:
        recorder += ["--save-map", str(save_map)]
    ros.start(recorder, name="coverage_recorder")
    ros.wait_for(lambda: read_jsonl(out), 60, "the coverage recorder")
    ros.run(["rosservice", "call", "/simulator/unpause"])
    return out
