"""One bag, the same figures from every entry point: `score_slam --from-run --json` and the
main job's figures.json (`mapping_demo --report-only`) both score through rosbook_eval.

The bag is written here, deterministically: a live run in the maze world as the main job
records it (ground truth, drifting odometry, SLAM's map → odom at its own stamps, /map),
with a SLAM map one cell off the true walls and a few false walls, so that no figure is
trivially 0 or 100 %.
"""

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tests"))
from roskit import ros_environment  # noqa: E402

WORLD = "maze"
START = (0.75, 0.75, 0.0)  # maze.yaml's start: where the map and odom frames begin
SECONDS = 30.0


def truth_pose(t):
    """A smooth loop from the start (world frame)."""
    return (
        START[0] + 2.0 * math.sin(t / 10.0),
        START[1] + 1.0 - math.cos(t / 10.0),
        t / 10.0,
    )


def drift(t):
    """Odometry's accumulated error (its odom frame against the map frame)."""
    return (0.01 * t, -0.006 * t, 0.004 * t)


def write_bag(path, truth_grid):
    import rosbag
    import rospy
    from geometry_msgs.msg import TransformStamped
    from nav_msgs.msg import OccupancyGrid, Odometry
    from rosbook_env.geometry import yaw_to_quaternion
    from rosbook_eval.poses import compose, inverse
    from tf2_msgs.msg import TFMessage

    def odometry(stamp, frame, pose):
        msg = Odometry()
        msg.header.stamp, msg.header.frame_id = stamp, frame
        msg.child_frame_id = "base_footprint"
        msg.pose.pose.position.x, msg.pose.pose.position.y = pose[:2]
        q = msg.pose.pose.orientation
        q.x, q.y, q.z, q.w = yaw_to_quaternion(pose[2])
        return msg

    map_from_world = inverse(START)
    with rosbag.Bag(str(path), "w") as bag:
        # Truth at 10 Hz, odometry at 20 Hz and map -> odom at 20 Hz, each at its own stamps,
        # so every track is interpolated.
        for t in np.arange(0.0, SECONDS, 0.1) + 0.03:
            stamp = rospy.Time.from_sec(1.0 + t)
            bag.write("/base_pose_ground_truth", odometry(stamp, "world", truth_pose(t)), stamp)
        for t in np.arange(0.0, SECONDS, 0.05):
            stamp = rospy.Time.from_sec(1.0 + t)
            in_map = compose(map_from_world, truth_pose(t))
            bag.write("/odom", odometry(stamp, "odom", compose(drift(t), in_map)), stamp)
        for t in np.arange(0.0, SECONDS, 0.05) + 0.025:
            stamp = rospy.Time.from_sec(1.0 + t)
            # SLAM undoes most of the drift, with a small wobble of its own.
            dx, dy, dth = inverse(drift(t))
            tf = TransformStamped()
            tf.header.stamp, tf.header.frame_id, tf.child_frame_id = stamp, "map", "odom"
            tf.transform.translation.x = dx + 0.02 * math.sin(t)
            tf.transform.translation.y = dy + 0.01 * math.cos(t / 2)
            r = tf.transform.rotation
            r.x, r.y, r.z, r.w = yaw_to_quaternion(dth + 0.003 * math.sin(t / 3))
            bag.write("/tf", TFMessage([tf]), stamp)
        cells, resolution, (ox, oy, _) = truth_grid
        # Plus a sprinkle of false walls in free space (about 1 free cell in 97).
        rows, cols = np.indices(cells.shape)
        cells = np.where((cells == 0) & ((rows * 7 + cols * 13) % 97 == 0), 100, cells)
        for last in (False, True):  # only the last /map counts
            grid = OccupancyGrid()
            stamp = rospy.Time.from_sec(1.0 + (SECONDS if last else 1.0))
            grid.header.stamp, grid.header.frame_id = stamp, "map"
            grid.info.resolution = resolution
            grid.info.height, grid.info.width = cells.shape
            # The true walls in the map frame, one cell off in x.
            grid.info.origin.position.x = ox - START[0] + resolution
            grid.info.origin.position.y = oy - START[1]
            grid.info.origin.orientation.w = 1.0
            grid.data = cells.flatten().tolist() if last else [-1] * cells.size
            bag.write("/map", grid, stamp)


# Two tool runs of a few seconds each; generous limits for a loaded machine.
@pytest.mark.timeout(700)
def test_score_slam_and_the_main_job_give_the_same_figures(tmp_path):
    from map_server.map_io import OccupancyMap, save_map
    from rosbook_eval.bag_tracks import read_last_map
    from rosbook_eval.truth import truth_grid

    env = ros_environment(0)  # neither tool talks to a master
    out = tmp_path / "out"
    out.mkdir()
    bag = out / f"{WORLD}.bag"
    write_bag(bag, truth_grid(WORLD))
    # What map_saver would have written at the end of the live run: the last /map.
    cells, resolution, origin = read_last_map(bag)
    save_map(out / f"{WORLD}_map", OccupancyMap(cells, resolution, origin))

    cli = subprocess.run(
        ["rosrun", "gmapping_lite", "score_slam", str(bag), "--world", WORLD, "--from-run"]
        + ["--json"],
        capture_output=True,
        text=True,
        env=env,
        timeout=300,
    )
    assert cli.returncode == 0, cli.stderr
    by_cli = json.loads(cli.stdout.strip().splitlines()[-1])
    demo = subprocess.run(
        ["rosrun", "rosbook_demo", "mapping_demo", "--world", WORLD, "--out", str(out)]
        + ["--report-only"],
        capture_output=True,
        text=True,
        env=env,
        timeout=300,
    )
    assert demo.returncode == 0, demo.stdout + demo.stderr
    by_demo = json.loads((out / "figures.json").read_text())

    pairs = [
        ("slam_rms", "slam_rms_m"),
        ("odom_rms", "odom_rms_m"),
        ("near_wall_fraction", "walls_within_tolerance"),
    ]
    pairs += [(a + "_start", b + "_start") for a, b in pairs]
    pairs += [("tolerance", "tolerance_m")]
    for cli_key, demo_key in pairs:
        assert by_cli[cli_key] == pytest.approx(by_demo[demo_key], rel=1e-9, abs=1e-12), (
            cli_key,
            by_cli,
            by_demo,
        )
    # The figures say what the bag was made to say: SLAM well under odometry's error, the
    # map one cell (0.05 m, within the 0.10 m tolerance) off the true walls, some false ones.
    print("score_slam:", by_cli, "\nfigures.json:", by_demo)
    assert by_cli["slam_rms"] < 0.5 * by_cli["odom_rms"]
    assert by_cli["slam_rms_start"] < 0.5 * by_cli["odom_rms_start"]
    assert 0.5 < by_cli["near_wall_fraction"] < 0.99
