"""Reliability matrix for the command-line tools: a bad argument, a missing master or an
unwritable destination gives one clear line naming the bad value or the fix, a usage exit
code, and writes nothing. Each row: (tool and arguments, exit code, text the output must hold).

{tmp} is the test's folder, {nested} a YAML nested 5000 levels deep, {dead} a master URI on
which nothing listens. No roscore is started: the rows are about what happens before one is
needed, or without one."""

import os
import socket
import subprocess

import pytest

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
}


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
    before = set(tmp_path.rglob("*"))
    argv = [a.replace("{tmp}", str(tmp_path)).replace("{nested}", str(nested)) for a in args]
    env = dict(os.environ, ROS_MASTER_URI=dead_master_uri(), PYENV_VERSION="system")
    done = subprocess.run(
        ["rosrun", *argv],
        capture_output=True,
        text=True,
        timeout=60,
        env=env,
        cwd=tmp_path,
        stdin=subprocess.DEVNULL,
    )
    output = done.stdout + done.stderr
    assert done.returncode == code, output
    assert text in output, output
    assert "Traceback" not in output, output
    assert set(tmp_path.rglob("*")) == before, "a failed run left files behind"
