"""slam_gmapping (gmapping_lite) against a synthetic laser robot: the book's interface
(topics, latched map, dynamic_map, tf, entropy, parameters) and its robustness to odd lasers,
missing tf and sim time. Every test runs under use_sim_time with the robot as /clock."""

import math
import re
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from slam_node_kit import (  # noqa: E402
    assert_room_mapped,
    cell,
    drive,
    load_turtlebot_tuning,
    near,
    record_drive,
    seconds,
    start_slam,
    wait_for_room_mapped,
)
from synthetic_scans import trajectory  # noqa: E402


def test_book_parameters_map_latched_stamped_and_served(ros):
    start_slam(ros, linearUpdate=0.1, angularUpdate=0.1, lskip=10, map_update_interval=1.0)
    entropy = ros.probe(["/slam_gmapping/entropy"], count=3, ready=False, timeout=180)
    diagnostics = ros.probe(["/diagnostics"], count=2, ready=False, timeout=180)
    drive(ros)
    # A subscriber arriving after the fact still gets the map: it is latched.
    grid = ros.echo("map")[0]["msg"]
    info = grid["info"]
    assert grid["header"]["frame_id"] == "map"
    assert 100.0 < seconds(grid["header"]["stamp"]) <= 141.0  # a scan's time, never 0
    assert info["resolution"] == pytest.approx(0.05)
    assert (info["origin"]["position"]["x"], info["origin"]["position"]["y"]) == (-10.0, -10.0)
    assert info["origin"]["orientation"]["w"] == 1.0
    assert (info["width"], info["height"]) == (400, 400)
    assert set(grid["data"]) <= {-1, 0, 100}
    assert_room_mapped(grid)
    meta = ros.echo("map_metadata")[0]["msg"]
    assert (meta["width"], meta["height"]) == (400, 400)
    # dynamic_map answers with the same map.
    served = ros.run(["rosservice", "call", "/dynamic_map"]).stdout
    assert "width: 400" in served and 'frame_id: "map"' in served
    # The filter's weight entropy is published: at most log(30).
    values = [m["msg"]["data"] for m in entropy.wait(190)]
    assert values and all(0.0 <= v <= math.log(30) + 1e-9 for v in values)
    # Scan counts on /diagnostics with each map: every scan received reaches the mapper
    # (throttle_scans 1); those it could not get to in time are counted as skipped.
    for message in diagnostics.wait(190):
        (status,) = message["msg"]["status"]
        assert status["name"] == "/slam_gmapping: scans"
        counts = {kv["key"]: int(kv["value"]) for kv in status["values"]}
        assert counts["scans received"] == counts["scans offered to the mapper"] > 0
        assert 0 <= counts["scans skipped (fell behind)"] < counts["scans received"]
        assert counts["updates"] > 0
        behind = status["message"].startswith("falling behind")
        assert status["level"] == (1 if behind else 0), status


def test_unused_private_parameters_are_named_once_at_start_up(ros):
    """The Turtlebot tuning file sets only parameters slam_gmapping reads; one it does not
    read (gmapping's llsamplerange, a misspelt name) is named in one warning at start-up."""

    def started(node):
        ros.wait_for(lambda: "waiting for scans" in ros.output(node), 60, "slam_gmapping to start")
        return [line for line in ros.output(node).splitlines() if "does not read" in line]

    load_turtlebot_tuning(ros)
    node = start_slam(ros)
    assert started(node) == [], ros.output(node)
    ros.stop(node)
    ros.run(["rosparam", "set", "/slam_gmapping/llsamplerange", "0.01"])
    ros.run(["rosparam", "set", "/slam_gmapping/partcles", "30"])
    node = start_slam(ros)
    (warning,) = started(node)
    assert "ignoring private parameters that gmapping_lite does not read" in warning
    assert "~llsamplerange" in warning and "~partcles" in warning, warning
    assert "~srr" not in warning and "~base_frame" not in warning, warning


def test_map_to_odom_tf_is_stamped_ahead_of_the_scans(ros):
    start_slam(ros)
    tf = ros.probe(["/tf"], duration=300, timeout=300)  # connected to slam_gmapping's tf
    drive(ros, "--duration", "12", "--speed", "2")
    stamps = [
        seconds(t["header"]["stamp"])
        for m in tf.stop()
        for t in m["msg"]["transforms"]
        if t["header"]["frame_id"] == "map" and t["child_frame_id"] == "odom"
    ]
    assert len(stamps) > 10, "map -> odom was not published"
    assert min(stamps) > 100.0  # never time 0
    assert max(stamps) <= 112.0 + 0.05 + 1e-6  # latest scan + transform_publish_period


UPDATE = re.compile(r"slam_gmapping: update (\d+) \(scan (\d+), t=([\d.]+)\)")
SCAN_PERIOD = 0.1  # synthetic_scans.py: a scan every 5 of its 50 Hz ticks


def robot_motion(t0, t1):
    """(path length, turning) of the synthetic robot between scan times t0 and t1, summed
    scan by scan as slam_gmapping sums its odometry (its trajectory: see synthetic_scans)."""
    poses = {round(s * 10): (x, th) for s, x, _, th in trajectory(45.0) if round(s * 50) % 5 == 0}
    first, last = round((t0 - 100.0) * 10), round((t1 - 100.0) * 10)
    linear = angular = 0.0
    for k in range(first, last):
        (xa, tha), (xb, thb) = poses[k], poses[k + 1]
        linear += abs(xb - xa)
        angular += abs(math.remainder(thb - tha, 2 * math.pi))
    return linear, angular


def assert_updates_follow(log, linear_update, angular_update):
    """Each filter update comes once the robot has moved linearUpdate or turned
    angularUpdate since the last one (never before), and at the first scan that does so
    (checked where no scan was dropped in between: a loaded machine may make the node
    skip scans, and then an update covers more motion). Returns the number of updates."""
    updates = [(int(n), int(scan), float(t)) for n, scan, t in UPDATE.findall(log)]
    assert [n for n, _, _ in updates] == list(range(len(updates)))
    tf_drops = "scans dropped so far" in log  # received, not used: the numbers do not show it
    checked = 0
    for (_, scan0, t0), (_, scan1, t1) in zip(updates, updates[1:], strict=False):
        linear, angular = robot_motion(t0, t1)
        assert linear >= linear_update - 1e-6 or angular >= angular_update - 1e-6, (t0, t1)
        if scan1 - scan0 == round((t1 - t0) / SCAN_PERIOD) and not tf_drops:
            linear, angular = robot_motion(t0, t1 - SCAN_PERIOD)
            assert linear < linear_update + 1e-6 and angular < angular_update + 1e-6, (t0, t1)
            checked += 1
    assert checked or tf_drops, "every interval between updates had dropped scans"
    return len(updates)


def test_diagnostics_and_update_thresholds_follow_the_parameters(ros):
    node = start_slam(ros, linearUpdate=1.0, angularUpdate=0.5)
    drive(ros)
    ros.stop(node)
    coarse = assert_updates_follow(ros.output(node), 1.0, 0.5)
    node = start_slam(ros, linearUpdate=0.1, angularUpdate=0.1)
    drive(ros)
    ros.stop(node)
    log = ros.output(node)
    fine = assert_updates_follow(log, 0.1, 0.1)
    # One turn (2 pi) and 4 m of driving, a scan every 0.1 s: the rule above gives 17 and 87
    # updates when no scan is skipped (every 16 scans turning, 50 driving; every 4 and 5).
    # Skipped scans (a loaded machine) can only make fewer.
    assert 0 < coarse <= 17 and coarse < fine <= 87, (coarse, fine)
    assert "best pose (" in log and "Neff" in log


def test_inf_beams_clear_free_space_up_to_max_urange(ros):
    start_slam(ros, maxUrange=6.0, map_update_interval=1.0)
    drive(ros, "--open-wall")
    grid = ros.echo("map")[0]["msg"]
    # Beyond the missing east wall nothing reflects: free out to maxUrange, then unknown.
    assert cell(grid, 4.5, 0.0) == 0
    assert cell(grid, 5.5, 0.0) == 0
    assert cell(grid, 9.0, 0.0) == -1  # beyond the last pose (x = 2) + maxUrange
    assert not near(grid, 4.0, 0.0, 100)


def test_upside_down_laser_maps_the_room_the_right_way_round(ros):
    node = start_slam(ros, map_update_interval=1.0)
    drive(ros, "--roll", str(math.pi))
    wait_for_room_mapped(ros, node)
    assert "upside down" in ros.output(node)


def test_asymmetric_scan_maps_the_room(ros):
    node = start_slam(ros, map_update_interval=1.0)
    drive(ros, "--angle-min", "-0.6", "--angle-max", "2.4")
    wait_for_room_mapped(ros, node)


def test_slightly_tilted_laser_is_handled_a_steep_one_is_refused(ros):
    node = start_slam(ros, map_update_interval=1.0)
    drive(ros, "--pitch", "0.05")
    wait_for_room_mapped(ros, node)
    ros.run(["rosnode", "kill", "/slam_gmapping"])
    node = start_slam(ros)
    drive(ros, "--pitch", "0.4", "--duration", "4")
    # The node may still be working through its queue when the drive ends.
    tilted = "scan plane is tilted 22.9"
    ros.wait_for(lambda: tilted in ros.output(node), 60, "the tilted-scan error")


def test_changed_beam_count_is_logged_once_and_handled(ros):
    node = start_slam(ros, map_update_interval=1.0)
    drive(ros, "--beams-after", "240")
    changed = "changed from 360 to 240 beams"
    ros.wait_for(lambda: changed in ros.output(node), 60, "the beam-count message")
    wait_for_room_mapped(ros, node)
    log = ros.output(node)
    assert log.count(changed) == 1, log[-3000:]


def test_missing_odometry_tf_is_named_and_throttled(ros):
    node = start_slam(ros)
    drive(ros, "--no-odom", "--duration", "20", "--speed", "2")
    log = ros.output(node)
    named = [line for line in log.splitlines() if "no odometry: transform from 'odom'" in line]
    assert named, log[-3000:]
    assert "to 'base_footprint' at the scan's stamp 1" in named[0]
    assert len(named) <= 4  # 200 scans dropped, a few throttled warnings
    assert "MessageFilter" not in log


def test_bag_played_with_clock(ros, tmp_path):
    bag = tmp_path / "data.bag"
    record_drive(ros, bag, "--duration", "40", "--speed", "4")
    node = start_slam(ros, map_update_interval=1.0)
    ros.run(["rosbag", "play", "--clock", "-r", "4", str(bag)], timeout=60)
    wait_for_room_mapped(ros, node)
    assert "update 5" in ros.output(node)
