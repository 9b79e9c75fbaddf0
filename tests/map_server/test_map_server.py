"""map_server as the book runs it: a YAML in, a latched /map, /map_metadata and /static_map out."""

import sys
import time
from pathlib import Path

import numpy as np
import pytest
import yaml

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "catkin_ws" / "src" / "map_server" / "src"))
from map_server import map_io  # noqa: E402
from roskit import launched_from_shell, run_in_ros_home  # noqa: E402

ORIGIN = (-1.5, 2.0, 0.0)
RESOLUTION = 0.1


def sample_map(tmp_path, name="lab"):
    """A 7 x 5 map whose cells are all different kinds, with a recognisable layout."""
    data = np.zeros((5, 7), dtype=np.int8)
    data[0, :] = 100  # bottom wall
    data[:, 6] = 100  # east wall
    data[4, :3] = -1  # unseen top-left corner
    omap = map_io.OccupancyMap(data, RESOLUTION, ORIGIN)
    _, yaml_path = map_io.save_map(tmp_path / name, omap)
    return data, yaml_path


def seconds(stamp):
    """The probe records times as {secs, nsecs} (or plain seconds)."""
    if isinstance(stamp, dict):
        return stamp["secs"] + stamp["nsecs"] * 1e-9
    return stamp


def check_info(info, width=7, height=5):
    assert (info["width"], info["height"]) == (width, height)
    assert info["resolution"] == pytest.approx(RESOLUTION)
    assert info["origin"]["position"]["x"] == pytest.approx(ORIGIN[0])
    assert info["origin"]["position"]["y"] == pytest.approx(ORIGIN[1])
    assert info["origin"]["orientation"]["w"] == pytest.approx(1.0)


def test_serves_a_latched_map_to_late_subscribers(ros, tmp_path):
    data, yaml_path = sample_map(tmp_path)
    server = ros.start(["rosrun", "map_server", "map_server", str(yaml_path)])
    ros.wait_for_topic("/map")
    time.sleep(1.0)  # subscribe well after the only publication: latching must deliver it
    before = time.time()
    (record,) = ros.echo("/map")
    grid = record["msg"]
    assert grid["header"]["frame_id"] == "map"
    stamp = seconds(grid["header"]["stamp"])
    assert before - 30 < stamp <= before  # stamped with ROS time (wall here) at load
    check_info(grid["info"])
    # Row-major, bottom row first: the bottom wall comes first.
    assert grid["data"] == data.reshape(-1).tolist()
    assert grid["data"][:7] == [100] * 7
    (meta,) = ros.echo("/map_metadata")
    check_info(meta["msg"])
    assert seconds(meta["msg"]["map_load_time"]) == pytest.approx(stamp)
    assert server.poll() is None


def test_static_map_service_answers(ros, tmp_path):
    data, yaml_path = sample_map(tmp_path)
    ros.start(["rosrun", "map_server", "map_server", str(yaml_path)])
    ros.wait_for_service("/static_map")
    done = ros.run(["rosservice", "call", "/static_map"])
    grid = yaml.safe_load(done.stdout)["map"]
    check_info(grid["info"])
    assert grid["data"] == data.reshape(-1).tolist()
    assert grid["header"]["frame_id"] == "map"


def test_books_command_from_maps_folder(ros):
    ros.start("rosrun map_server map_server willow.yaml", cwd=REPO / "maps")
    ros.wait_for_topic("/map_metadata")
    (meta,) = ros.echo("/map_metadata")
    expected = map_io.load_map(REPO / "maps" / "willow.yaml")
    info = meta["msg"]
    assert (info["width"], info["height"]) == (expected.width, expected.height)
    assert info["resolution"] == pytest.approx(expected.resolution)
    assert ros.topics() >= {"/map", "/map_metadata", "/rosout"}


def test_frame_id_parameter_rotated_origin_unknown_key(ros, tmp_path):
    _, yaml_path = sample_map(tmp_path)
    rotated = tmp_path / "rotated.yaml"
    text = yaml_path.read_text().replace("0.000000]", "0.500000]") + "colour: blue\n"
    rotated.write_text(text)
    server = ros.start(["rosrun", "map_server", "map_server", str(rotated), "_frame_id:=world"])
    ros.wait_for_topic("/map")
    (record,) = ros.echo("/map")
    assert "rotated.yaml: unknown key 'colour' ignored" in ros.output(server)
    assert record["msg"]["header"]["frame_id"] == "world"
    q = record["msg"]["info"]["origin"]["orientation"]
    assert (q["z"], q["w"]) == pytest.approx((np.sin(0.25), np.cos(0.25)))


def test_sim_time_stamp_follows_the_clock(ros, tmp_path):
    _, yaml_path = sample_map(tmp_path)
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    ros.start(["rosrun", "map_server", "map_server", str(yaml_path)])
    ros.wait_for_topic("/map")
    probe = ros.probe(["/map"], count=2, timeout=30)
    ros.start(["rostopic", "pub", "-r", "20", "/clock", "rosgraph_msgs/Clock", "clock: {secs: 42}"])
    first, second = probe.wait(40)
    assert seconds(first["msg"]["header"]["stamp"]) == 0  # no clock yet when it loaded
    assert seconds(second["msg"]["header"]["stamp"]) == pytest.approx(42.0)
    assert seconds(second["msg"]["info"]["map_load_time"]) == pytest.approx(42.0)


def test_deprecated_image_resolution_form_and_slashed_frame(ros, tmp_path):
    data, yaml_path = sample_map(tmp_path)
    ros.start(
        ["rosrun", "map_server", "map_server", str(tmp_path / "lab.pgm"), "0.25"]
        + ["_frame_id:=/floor"]
    )
    ros.wait_for_topic("/map")
    (record,) = ros.echo("/map")
    assert record["msg"]["header"]["frame_id"] == "floor"  # no tf2-invalid leading slash
    info = record["msg"]["info"]
    assert info["resolution"] == pytest.approx(0.25)
    assert info["origin"]["position"]["x"] == 0.0
    assert record["msg"]["data"] == data.reshape(-1).tolist()


def test_bad_yaml_is_a_clear_error_and_harms_nothing(ros, tmp_path):
    _, good = sample_map(tmp_path)
    server = ros.start(["rosrun", "map_server", "map_server", str(good)])
    ros.wait_for_topic("/map")
    bad = tmp_path / "broken.yaml"
    bad.write_text("image: lab.pgm\nresolution: fine\norigin: [0, 0, 0]\nnegate: 0\n")
    done = ros.run(["rosrun", "map_server", "map_server", str(bad)], check=False)
    assert done.returncode != 0
    assert "broken.yaml" in done.stderr and "missing key" in done.stderr
    done = ros.run(["rosrun", "map_server", "map_server", "no_such_map.yaml"], check=False)
    assert done.returncode != 0
    assert "no_such_map.yaml: map YAML file not found" in done.stderr
    # The running map_server (same node name) was not replaced by the failed ones.
    time.sleep(0.5)
    assert server.poll() is None
    assert ros.echo("/map")[0]["msg"]["info"]["width"] == 7


def test_relative_map_file_under_roslaunch_is_read_from_the_shell_folder(ros, tmp_path):
    """`rosrun map_server map_saver -f mymap`, then `roslaunch ... map_file:=mymap.yaml` from
    the same folder: the map is found although the node runs in ~/.ros, and the log says
    which file it loaded."""
    shell, _, env = launched_from_shell(ros, tmp_path)
    data, _ = sample_map(shell, "mymap")
    launch = tmp_path / "serve.launch"
    launch.write_text(
        '<launch><arg name="map_file"/><node pkg="map_server" type="map_server" '
        'name="map_server" output="screen" args="$(arg map_file)"/></launch>'
    )
    sim = ros.start(["roslaunch", str(launch), "map_file:=mymap.yaml"], env=env, cwd=shell)
    ros.wait_for_topic("/map")
    assert ros.echo("/map")[0]["msg"]["data"] == data.reshape(-1).tolist()
    ros.wait_for(
        lambda: (
            f"Loaded the map {shell / 'mymap.yaml'} (relative to the launching shell"
            in ros.output(sim)
        ),
        what="map_server to log the file it loaded",
    )


def test_relative_map_file_found_nowhere_names_both_folders_and_the_fix(ros, tmp_path):
    shell, ros_home, env = launched_from_shell(ros, tmp_path)
    done = run_in_ros_home(["rosrun", "map_server", "map_server", "mymap.yaml"], env, ros_home)
    assert done.returncode == 1
    assert "mymap.yaml: map YAML file not found" in done.stderr
    assert f"looked in {ros_home} and {shell}" in done.stderr
    assert "map_file:=$(pwd)/mymap.yaml" in done.stderr
