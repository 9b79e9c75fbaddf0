"""The explorer node on its own: bad parameters, and its topics on a tiny known world
(a latched map, a static pose, a scan) without a simulator."""

import math
from pathlib import Path

HERE = Path(__file__).resolve().parent
PYTHON = "/usr/bin/python3"


def test_bad_parameter_is_a_clear_fatal_error(ros):
    done = ros.run(
        ["rosrun", "explorer", "explorer.py", "_max_linear:=-1"], timeout=60, check=False
    )
    assert done.returncode == 2
    assert "max_linear" in done.stdout + done.stderr


def test_goal_path_and_done_on_a_small_room(ros):
    ros.run(["rosparam", "set", "/use_sim_time", "false"])
    ros.start([PYTHON, str(HERE / "fake_world.py")], name="fake_world")
    ros.wait_for_topic("map", timeout=60)
    node = ros.start(
        ["rosrun", "explorer", "explorer.py", "cmd_vel:=navi", "_initial_spin:=0"], name="explorer"
    )
    ros.wait_for_topic("explorer/done", timeout=60)
    got = ros.probe(["explorer/goal", "explorer/path", "navi"], count=1, timeout=90).wait(100)
    goal = next(m["msg"] for m in got if m["topic"] == "explorer/goal")
    path = next(m["msg"] for m in got if m["topic"] == "explorer/path")
    assert goal["header"]["frame_id"] == "map" and path["header"]["frame_id"] == "map"
    # The room's unknown half lies at x > 2: the goal looks into it from the known half.
    gx = goal["pose"]["position"]["x"]
    assert 0.0 < gx <= 2.0
    first = path["poses"][0]["pose"]["position"]
    assert math.hypot(first["x"] - 0.5, first["y"] - 1.0) < 0.2  # starts at the robot
    twist = next(m["msg"] for m in got if m["topic"] == "navi")
    assert abs(twist["linear"]["x"]) <= 0.35 and abs(twist["angular"]["z"]) <= 1.0
    done = ros.echo("explorer/done", count=1)[0]["msg"]
    assert done["data"] is False
    # It says which frames it works in, and reports the goal it published.
    gy = goal["pose"]["position"]["y"]
    reported = f"goal ({gx:.2f}, {gy:.2f}): path "
    ros.wait_for(lambda: reported in ros.output(node), 60, f"the log line '{reported}...'")
    assert "explorer: exploring (map -> base_footprint)" in ros.output(node)


def test_done_when_nothing_is_left_to_explore(ros):
    ros.run(["rosparam", "set", "/use_sim_time", "false"])
    ros.start([PYTHON, str(HERE / "fake_world.py"), "_unknown_half:=false"], name="fake_world")
    ros.wait_for_topic("map", timeout=60)
    node = ros.start(
        ["rosrun", "explorer", "explorer.py", "cmd_vel:=navi", "_initial_spin:=0"], name="explorer"
    )
    ros.wait_for(lambda: "exploration done" in ros.output(node), 60, "exploration done")
    done = ros.echo("explorer/done", count=1)[0]["msg"]  # latched
    assert done["data"] is True
