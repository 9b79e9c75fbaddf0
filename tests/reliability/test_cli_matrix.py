"""Reliability matrix for the command-line tools: a bad argument, a missing master or an
unwritable destination gives one clear line naming the bad value or the fix, a usage exit
code, and writes nothing. Each row: (tool and arguments, exit code, text the output must hold).

{tmp} is the test's folder, {nested} a YAML nested 5000 levels deep, {unfinished} and {noscan}
bags (write_bags), {dead} a master URI on
which nothing listens. No roscore is started: the rows are about what happens before one is
needed, or without one."""

import os
import socket
import subprocess

import pytest
from roskit import without_rosrun

CASES = {
    # map_saver
    "map_saver timeout nan": (
        ["map_server", "map_saver", "--timeout", "nan"],
        2,
        "not a finite number",
    ),
    "map_saver timeout -1": (["map_server", "map_saver", "--timeout", "-1"], 2, "0 or more"),
    "map_saver empty name": (["map_server", "map_saver", "-f", ""], 2, "-f needs a base name"),
    "map_saver missing folder": (["map_server", "map_saver", "-f", "{tmp}/no/m"], 2, "mkdir -p"),
    "map_saver occ 0": (["map_server", "map_saver", "--occ", "0"], 2, "occ"),
    "map_saver free above occ": (
        ["map_server", "map_saver", "--occ", "50", "--free", "60"],
        2,
        "free",
    ),
    "map_saver no master": (
        ["map_server", "map_saver", "-f", "{tmp}/m"],
        1,
        "start `roscore` first",
    ),
    # map_server
    "map_server no file": (["map_server", "map_server", "{tmp}/none.yaml"], 1, "not found"),
    "map_server nested yaml": (["map_server", "map_server", "{nested}"], 1, "nested too deeply"),
    "map_server no argument": (["map_server", "map_server"], 1, "map_server MAP.yaml"),
    # rqt_lite
    "rqt_plot missing folder": (
        ["rqt_lite", "rqt_plot", "--output", "{tmp}/no/p.png", "/x/data"],
        2,
        "mkdir -p",
    ),
    "rqt_plot bad suffix": (["rqt_lite", "rqt_plot", "--output", "{tmp}/p.txt", "/x"], 2, ".png"),
    "rqt_plot duration nan": (
        ["rqt_lite", "rqt_plot", "--output", "{tmp}/p.png", "-d", "nan", "/x"],
        2,
        "not a finite number",
    ),
    "rqt_plot duration 0": (
        ["rqt_lite", "rqt_plot", "--output", "{tmp}/p.png", "-d", "0", "/x"],
        2,
        "greater than 0",
    ),
    "rqt_plot no master": (
        ["rqt_lite", "rqt_plot", "--output", "{tmp}/p.png", "-d", "1", "/x/data"],
        1,
        "start `roscore` first",
    ),
    "rqt_graph missing folder": (
        ["rqt_lite", "rqt_graph", "--output", "{tmp}/no/g.png"],
        2,
        "mkdir -p",
    ),
    "rqt_graph output is a folder": (
        ["rqt_lite", "rqt_graph", "--output", "{tmp}/empty.png/"],
        2,
        "--output must end in",
    ),
    # the main job
    "mapping_demo sim-seconds nan": (
        ["rosbook_demo", "mapping_demo", "--sim-seconds", "nan", "--out", "{tmp}/o"],
        2,
        "not a finite number",
    ),
    "mapping_demo sim-seconds 0": (
        ["rosbook_demo", "mapping_demo", "--sim-seconds", "0", "--out", "{tmp}/o"],
        2,
        "greater than 0",
    ),
    "mapping_demo speed -1": (
        ["rosbook_demo", "mapping_demo", "--speed", "-1", "--out", "{tmp}/o"],
        2,
        "0 or more",
    ),
    "mapping_demo speed abc": (
        ["rosbook_demo", "mapping_demo", "--speed", "abc", "--out", "{tmp}/o"],
        2,
        "not a number",
    ),
    "mapping_demo particles 0": (
        ["rosbook_demo", "mapping_demo", "--particles", "0", "--out", "{tmp}/o"],
        2,
        "--particles",
    ),
    "mapping_demo report-only on a missing folder": (
        ["rosbook_demo", "mapping_demo", "--report-only", "--out", "{tmp}/none"],
        1,
        "needs a finished run",
    ),
    "mapping_demo report-only on an empty folder": (
        ["rosbook_demo", "mapping_demo", "--report-only", "--out", "{tmp}/empty"],
        1,
        "needs a finished run",
    ),
    "mapping_demo out under a file": (
        ["rosbook_demo", "mapping_demo", "--out", "{tmp}/file/sub"],
        1,
        "cannot create the output folder",
    ),
    # world tools
    "world_to_map empty name": (
        ["bullet_turtlebot", "world_to_map", "maze", "-f", ""],
        2,
        "-f needs a base name",
    ),
    "world_to_map resolution -1": (
        ["bullet_turtlebot", "world_to_map", "maze", "--resolution", "-1", "-f", "{tmp}/w"],
        2,
        "--resolution must be > 0",
    ),
    "score_slam tolerance -1": (
        ["gmapping_lite", "score_slam", "{nested}", "--world", "maze", "--tolerance", "-1"],
        2,
        "argument --tolerance: '-1' must be 0 or more",
    ),
    "score_slam tolerance nan": (
        ["gmapping_lite", "score_slam", "{nested}", "--world", "maze", "--tolerance", "nan"],
        2,
        "argument --tolerance: 'nan' is not a finite number",
    ),
    "score_slam missing bag": (
        ["gmapping_lite", "score_slam", "{tmp}/none.bag", "--world", "maze"],
        1,
        "none.bag: no such bag file",
    ),
    "score_slam not a bag": (
        ["gmapping_lite", "score_slam", "{nested}", "--world", "maze"],
        1,
        "cannot read the bag",
    ),
    "score_slam unknown world": (
        ["gmapping_lite", "score_slam", "{nested}", "--world", "nosuchworld"],
        1,
        "cannot draw the true map of --world",
    ),
    "slam_offline param without a value": (
        ["gmapping_lite", "slam_offline", "{nested}", "--param", "nonsense"],
        2,
        "bad --param 'nonsense'",
    ),
    "slam_offline param not a number": (
        ["gmapping_lite", "slam_offline", "{nested}", "--param", "delta=abc"],
        2,
        "bad --param 'delta=abc'",
    ),
    "world_to_map unknown world": (
        ["bullet_turtlebot", "world_to_map", "nosuch", "-f", "{tmp}/w"],
        1,
        "cannot open",
    ),
    "world_to_map resolution nan": (
        ["bullet_turtlebot", "world_to_map", "maze", "--resolution", "nan", "-f", "{tmp}/w"],
        2,
        "usage",
    ),
    "make_worlds unknown family": (
        ["bullet_turtlebot", "make_worlds.py", "--family", "nosuch", "--seed", "1", "{tmp}"],
        2,
        "invalid choice",
    ),
    "make_worlds name without family": (
        ["bullet_turtlebot", "make_worlds.py", "--name", "x", "{tmp}"],
        2,
        "--name needs --family",
    ),
    "make_worlds name with a folder": (
        ["bullet_turtlebot", "make_worlds.py", "--family", "lab", "--name", "a/b", "{tmp}"],
        2,
        "--name 'a/b' must be a file name without a folder",
    ),
    "make_worlds empty name": (
        ["bullet_turtlebot", "make_worlds.py", "--family", "lab", "--name", "", "{tmp}"],
        2,
        "--name '' must be a file name without a folder",
    ),
    "make_worlds output is a file": (
        ["bullet_turtlebot", "make_worlds.py", "--family", "lab", "{tmp}/file"],
        2,
        "file is a file; give a folder",
    ),
    "make_worlds output under a file": (
        ["bullet_turtlebot", "make_worlds.py", "--family", "lab", "{tmp}/file/sub"],
        1,
        "cannot create the folder",
    ),
    "make_worlds seed abc": (
        ["bullet_turtlebot", "make_worlds.py", "--family", "lab", "--seed", "abc", "{tmp}"],
        2,
        "argument --seed: invalid int value: 'abc'",
    ),
    "world_to_map no world": (["bullet_turtlebot", "world_to_map"], 2, "no world given"),
    "world_to_map two worlds": (
        ["bullet_turtlebot", "world_to_map", "maze", "office", "-f", "{tmp}/w"],
        2,
        "more than one world given",
    ),
    "world_to_map unknown option": (
        ["bullet_turtlebot", "world_to_map", "maze", "--bogus"],
        2,
        "unknown option --bogus",
    ),
    "world_to_map missing folder": (
        ["bullet_turtlebot", "world_to_map", "maze", "-f", "{tmp}/no/w"],
        1,
        "does not exist (create it with: mkdir -p",
    ),
    "world_to_map resolution inf": (
        ["bullet_turtlebot", "world_to_map", "maze", "--resolution", "inf", "-f", "{tmp}/w"],
        2,
        "--resolution must be > 0 and finite",
    ),
    "world_to_map resolution too fine": (
        ["bullet_turtlebot", "world_to_map", "maze", "--resolution", "0.0001", "-f", "{tmp}/w"],
        1,
        "map would be too large",
    ),
    "world_to_map margin nan": (
        ["bullet_turtlebot", "world_to_map", "maze", "--margin", "nan", "-f", "{tmp}/w"],
        2,
        "--margin must be >= 0 and finite",
    ),
    "world_to_map margin -5": (
        ["bullet_turtlebot", "world_to_map", "maze", "--margin", "-5", "-f", "{tmp}/w"],
        2,
        "--margin must be >= 0 and finite",
    ),
    "world_to_map margin 1e9": (
        ["bullet_turtlebot", "world_to_map", "maze", "--margin", "1e9", "-f", "{tmp}/w"],
        1,
        "map would be too large at this resolution and margin",
    ),
    "world_to_map min-height nan": (
        ["bullet_turtlebot", "world_to_map", "maze", "--min-height", "nan", "-f", "{tmp}/w"],
        2,
        "--min-height must be a finite number",
    ),
    # map_server's other tools
    "make_building_map empty name": (
        ["map_server", "make_building_map", "-f", ""],
        2,
        "-f needs a base name",
    ),
    "make_building_map missing folder": (
        ["map_server", "make_building_map", "-f", "{tmp}/no/b"],
        2,
        "mkdir -p",
    ),
    "make_building_map resolution nan": (
        ["map_server", "make_building_map", "--resolution", "nan", "-f", "{tmp}/b"],
        2,
        "--resolution must be between 0.005 and 1.0 m",
    ),
    "map_bench sizes 0": (
        ["map_server", "map_bench", "--sizes", "0"],
        2,
        "sizes between 1 and 10000",
    ),
    "map_bench repeat 0": (
        ["map_server", "map_bench", "--repeat", "0"],
        2,
        "--repeat must be >= 1",
    ),
    "map_saver occ 101": (["map_server", "map_saver", "--occ", "101"], 2, "occ"),
    "map_saver timeout abc": (
        ["map_server", "map_saver", "--timeout", "abc"],
        2,
        "'abc' is not a number",
    ),
    # gmapping_lite's tools
    "waypoint_driver speed nan": (
        ["gmapping_lite", "waypoint_driver", "--speed", "nan"],
        2,
        "argument --speed: 'nan' is not a finite number",
    ),
    "waypoint_driver speed -1": (
        ["gmapping_lite", "waypoint_driver", "--speed", "-1"],
        2,
        "argument --speed: '-1' must be greater than 0",
    ),
    "waypoint_driver turn 0": (
        ["gmapping_lite", "waypoint_driver", "--turn", "0"],
        2,
        "argument --turn: '0' must be greater than 0",
    ),
    "waypoint_driver unknown route": (
        ["gmapping_lite", "waypoint_driver", "--route", "nosuch"],
        2,
        "invalid choice: 'nosuch'",
    ),
    "waypoint_driver no waypoints file": (
        ["gmapping_lite", "waypoint_driver", "--waypoints", "{tmp}/none.yaml"],
        1,
        "waypoint_driver: cannot read {tmp}/none.yaml",
    ),
    "waypoint_driver waypoints not a list": (
        ["gmapping_lite", "waypoint_driver", "--waypoints", "{tmp}/file"],
        1,
        "expected a non-empty list of [x, y] or [x, y, spin]",
    ),
    "slam_bench unknown argument": (
        ["gmapping_lite", "slam_bench", "--nosuch"],
        2,
        "slam_bench: unknown argument '--nosuch'",
    ),
    "slam_bench only 0 particles": (
        ["gmapping_lite", "slam_bench", "--only", "0", "640"],
        2,
        "--only PARTICLES must be a whole number in [1, 1000], got '0'",
    ),
    "slam_bench only beams abc": (
        ["gmapping_lite", "slam_bench", "--only", "30", "abc"],
        2,
        "--only BEAMS must be a whole number in [2, 10000], got 'abc'",
    ),
    "slam_bench only one number": (
        ["gmapping_lite", "slam_bench", "--only", "30"],
        2,
        "wrong number of arguments",
    ),
    "slam_bench help": (["gmapping_lite", "slam_bench", "--help"], 0, "usage: slam_bench"),
    "slam_offline help": (["gmapping_lite", "slam_offline", "--help"], 0, "usage: slam_offline"),
    "record_office_bag no arguments": (
        ["gmapping_lite", "record_office_bag"],
        2,
        "usage: record_office_bag OUT.bag",
    ),
    "record_office_bag missing folder": (
        ["gmapping_lite", "record_office_bag", "{tmp}/no/o.bag"],
        2,
        "does not exist (create it with: mkdir -p",
    ),
    "record_office_bag not a bag name": (
        ["gmapping_lite", "record_office_bag", "{tmp}/o.txt"],
        2,
        "must end in .bag",
    ),
    "record_office_bag speed abc": (
        ["gmapping_lite", "record_office_bag", "{tmp}/o.bag", "abc"],
        2,
        "speed 'abc' must be a number >= 0",
    ),
    "record_office_bag seed -1": (
        ["gmapping_lite", "record_office_bag", "{tmp}/o.bag", "4", "-1"],
        2,
        "seed '-1' must be a whole number >= 0",
    ),
    "score_slam unknown alignment": (
        ["gmapping_lite", "score_slam", "{nested}", "--world", "maze", "--alignment", "x"],
        2,
        "invalid choice: 'x'",
    ),
    "slam_offline no bag given": (["gmapping_lite", "slam_offline"], 2, "no bag given"),
    "slam_offline unknown option": (
        ["gmapping_lite", "slam_offline", "{nested}", "--bogus"],
        2,
        "unknown option --bogus",
    ),
    # the main job's other arguments
    "mapping_demo particles 100000": (
        ["rosbook_demo", "mapping_demo", "--particles", "100000", "--out", "{tmp}/o"],
        2,
        "--particles must be 1 to 1000 (each particle holds a map), got 100000",
    ),
    "mapping_demo seed -5": (
        ["rosbook_demo", "mapping_demo", "--seed", "-5", "--out", "{tmp}/o"],
        2,
        "--seed must be a whole number from 0 to 2147483647, got -5",
    ),
    "mapping_demo family seed abc": (
        ["rosbook_demo", "mapping_demo", "--world", "lab:abc", "--out", "{tmp}/o"],
        2,
        "--world lab:abc: the seed 'abc' is not a whole number",
    ),
    "mapping_demo unknown family": (
        ["rosbook_demo", "mapping_demo", "--world", "nosuch:1", "--out", "{tmp}/o"],
        2,
        "unknown world family 'nosuch'",
    ),
    "mapping_demo unknown driver": (
        ["rosbook_demo", "mapping_demo", "--driver", "nosuch", "--out", "{tmp}/o"],
        2,
        "invalid choice: 'nosuch'",
    ),
    "mapping_demo missing world file": (
        ["rosbook_demo", "mapping_demo", "--world", "{tmp}/none.yaml", "--out", "{tmp}/o"],
        1,
        "--world {tmp}/none.yaml: world file '{tmp}/none.yaml': cannot open",
    ),
    "mapping_demo sim-seconds beyond ROS time": (
        ["rosbook_demo", "mapping_demo", "--sim-seconds", "1e30", "--out", "{tmp}/o"],
        2,
        "--sim-seconds must be at most 4e9",
    ),
    "mapping_demo sim-param without a value": (
        ["rosbook_demo", "mapping_demo", "--sim-param", "range_max", "--out", "{tmp}/o"],
        2,
        "--sim-param wants NAME=VALUE, got 'range_max'",
    ),
    "mapping_demo unknown sim-param": (
        ["rosbook_demo", "mapping_demo", "--sim-param", "scan_fov=270", "--out", "{tmp}/o"],
        2,
        "--sim-param scan_fov=270: unknown simulator parameter 'scan_fov'; the simulator "
        "reads: accel_angular, accel_linear,",
    ),
    # the book's listings (chapters 3-5, 8) and rqt_lite
    "simple_action_client duration nan": (
        ["basics", "simple_action_client.py", "--duration", "nan"],
        2,
        "seconds must be finite",
    ),
    "simple_action_client duration abc": (
        ["basics", "simple_action_client.py", "--duration", "abc"],
        2,
        "not a number of seconds: 'abc'",
    ),
    "fancy_action_client preempt-after -1": (
        ["basics", "fancy_action_client.py", "--preempt-after", "-1"],
        2,
        "a delay cannot be negative: '-1'",
    ),
    "fancy_action_client duration inf": (
        ["basics", "fancy_action_client.py", "--duration", "inf"],
        2,
        "seconds must be finite",
    ),
    "service_server unknown mode": (
        ["basics", "service_server.py", "--mode", "nosuch"],
        2,
        "invalid choice: 'nosuch'",
    ),
    "service_client help": (["basics", "service_client.py", "-h"], 0, "usage: service_client.py"),
    "keyboard_teleop without a terminal": (
        ["teleop_bot", "keyboard_teleop.py"],
        1,
        "standard input is not a terminal (TTY)",
    ),
    "rqt_plot no fields": (
        ["rqt_lite", "rqt_plot", "--output", "{tmp}/p.png"],
        2,
        "the following arguments are required: fields",
    ),
    "rqt_graph no master": (
        ["rqt_lite", "rqt_graph", "--output", "{tmp}/g.png"],
        1,
        "rqt_graph: cannot reach the ROS master",
    ),
    # SLAM offline
    "slam_offline no bag": (
        ["gmapping_lite", "slam_offline", "{tmp}/none.bag", "--out", "{tmp}/m"],
        1,
        "cannot open",
    ),
    "slam_offline not a bag": (
        ["gmapping_lite", "slam_offline", "{nested}", "--out", "{tmp}/m"],
        1,
        "cannot open",
    ),
    "slam_offline out in a missing folder": (
        ["gmapping_lite", "slam_offline", "{noscan}", "--out", "{tmp}/no/m"],
        1,
        "folder {tmp}/no does not exist (create it with: mkdir -p",
    ),
    "slam_offline trajectory under a file": (
        ["gmapping_lite", "slam_offline", "{noscan}", "--trajectory", "{tmp}/file/t.csv"],
        1,
        "{tmp}/file is a file, not a folder",
    ),
    "slam_offline unfinished bag": (
        ["gmapping_lite", "slam_offline", "{unfinished}", "--out", "{tmp}/m"],
        1,
        "`rosbag reindex BAG` rebuilds its index",
    ),
    "score_slam unfinished bag": (
        ["gmapping_lite", "score_slam", "{unfinished}", "--world", "maze"],
        1,
        "the bag has no index (an unfinished recording?): `rosbag reindex BAG`",
    ),
    "slam_offline bag without scans": (
        ["gmapping_lite", "slam_offline", "{noscan}", "--scan", "/base_scan", "--out", "{tmp}/m"],
        1,
        "no messages on /base_scan (its LaserScan topics: /scan; choose one with --scan TOPIC)",
    ),
}


def write_bags(folder):
    """{unfinished}: a bag as `rosbag record` leaves it when killed (its header's index
    position still 0); {noscan}: a finished bag holding one LaserScan on /scan."""
    import shutil

    import rosbag
    import rospy
    from sensor_msgs.msg import LaserScan

    live = rosbag.Bag(str(folder / "live.bag"), "w")
    live.write("/scan", LaserScan(), rospy.Time(1))
    live.flush()
    shutil.copy(folder / "live.bag", folder / "unfinished.bag")
    live.close()
    (folder / "live.bag").rename(folder / "noscan.bag")


def dead_master_uri():
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return f"http://127.0.0.1:{sock.getsockname()[1]}"  # closed again when we return


@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_input_is_a_clear_error_and_writes_nothing(case, tmp_path):
    args, code, text = CASES[case]
    nested = tmp_path / "nested.yaml"
    nested.write_text("image: " + "[" * 5000 + "]" * 5000)
    (tmp_path / "file").write_text("a file, not a folder")
    (tmp_path / "empty").mkdir()
    if any(a in ("{unfinished}", "{noscan}") for a in args):
        write_bags(tmp_path)
    before = set(tmp_path.rglob("*"))
    argv = [
        a.replace("{tmp}", str(tmp_path))
        .replace("{nested}", str(nested))
        .replace("{unfinished}", str(tmp_path / "unfinished.bag"))
        .replace("{noscan}", str(tmp_path / "noscan.bag"))
        for a in args
    ]
    env = dict(os.environ, ROS_MASTER_URI=dead_master_uri(), PYENV_VERSION="system")
    done = subprocess.run(
        without_rosrun(["rosrun", *argv], env),
        capture_output=True,
        text=True,
        timeout=60,
        env=env,
        cwd=tmp_path,
        stdin=subprocess.DEVNULL,
    )
    output = done.stdout + done.stderr
    assert done.returncode == code, output
    assert text.replace("{tmp}", str(tmp_path)) in output, output
    assert "Traceback" not in output, output
    assert set(tmp_path.rglob("*")) == before, "a failed run left files behind"
