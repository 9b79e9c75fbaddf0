"""map_saver as the book runs it: save the published map as map.pgm + map.yaml, then exit."""

import sys
import time
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "catkin_ws" / "src" / "map_server" / "src"))
from map_server import map_io  # noqa: E402

ORIGIN = (-10.0, -7.5, 0.0)


def served_map(tmp_path):
    """A 40 x 30 trinary map with a room drawn in it, saved for map_server."""
    rng = np.random.default_rng(3)
    data = rng.choice(np.array([-1, 0, 100], dtype=np.int8), size=(30, 40), p=[0.2, 0.6, 0.2])
    data[5, 5:20] = 100
    data[0, 0] = 100  # bottom-left corner occupied: catches a missing row flip
    data[29, 0] = 0
    source = tmp_path / "source"
    source.mkdir()
    map_io.save_map(source / "room", map_io.OccupancyMap(data, 0.05, ORIGIN))
    return data, source / "room.yaml"


def run_saver(ros, args, cwd, timeout=60):
    return ros.run(
        ["rosrun", "map_server", "map_saver", *args], timeout=timeout, cwd=cwd, check=False
    )


def check_saved(base, data):
    saved = map_io.load_map(base.with_suffix(".yaml"))
    np.testing.assert_array_equal(saved.data, data)
    assert saved.resolution == pytest.approx(0.05)
    assert saved.origin == pytest.approx(ORIGIN)


def test_saves_the_latched_map_like_the_book(ros, tmp_path):
    data, yaml_path = served_map(tmp_path)
    ros.start(["rosrun", "map_server", "map_server", str(yaml_path)])
    ros.wait_for_topic("/map")
    out = tmp_path / "out"
    out.mkdir()
    done = run_saver(ros, [], cwd=out)
    assert done.returncode == 0, done.stdout + done.stderr
    lines = done.stdout
    for expected in (
        "Waiting for the map",
        "Received a 40 X 30 map @ 0.050 m/pix",
        "Writing map occupancy data to map.pgm",
        "Done",
    ):
        assert expected in lines
    assert (out / "map.pgm").read_bytes().startswith(b"P5\n")
    assert (out / "map.yaml").read_text() == (
        "image: map.pgm\n"
        "resolution: 0.050000\n"
        "origin: [-10.000000, -7.500000, 0.000000]\n"
        "negate: 0\n"
        "occupied_thresh: 0.65\n"
        "free_thresh: 0.196\n\n"
    )
    check_saved(out / "map", data)


def test_name_and_topic_remapping(ros, tmp_path):
    data, yaml_path = served_map(tmp_path)
    ros.start(["rosrun", "map_server", "map_server", str(yaml_path), "map:=/robot/map"])
    ros.wait_for_topic("/robot/map")
    done = run_saver(ros, ["-f", "office", "map:=/robot/map"], cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "Writing map occupancy data to office.pgm" in done.stdout
    assert "image: office.pgm\n" in (tmp_path / "office.yaml").read_text()
    check_saved(tmp_path / "office", data)


def test_falls_back_to_the_dynamic_map_service(ros, tmp_path):
    data, yaml_path = served_map(tmp_path)
    # A real map_server whose topic is elsewhere and whose service is called dynamic_map,
    # as slam_gmapping offers it.
    ros.start(
        ["rosrun", "map_server", "map_server", str(yaml_path)]
        + ["map:=/hidden_map", "static_map:=dynamic_map"]
    )
    ros.wait_for_service("/dynamic_map")
    done = run_saver(ros, ["-f", str(tmp_path / "auto")], cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "from the /dynamic_map service" in done.stdout
    check_saved(tmp_path / "auto", data)
    done = run_saver(ros, ["--service", "-f", str(tmp_path / "asked")], cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    check_saved(tmp_path / "asked", data)


def test_occ_and_free_thresholds(ros, tmp_path):
    # A scale-mode map gives in-between cells, which the thresholds sort out.
    grey = np.array([[254, 230, 150, 100, 0]], dtype=np.uint8)
    (tmp_path / "s.pgm").write_bytes(b"P5\n5 1\n255\n" + grey.tobytes())
    (tmp_path / "s.yaml").write_text(
        "image: s.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.05\nmode: scale\n"
    )
    served = map_io.load_map(tmp_path / "s.yaml").data[0].tolist()
    assert served[0] == 0 and served[4] == 100 and all(0 < v < 100 for v in served[1:4])
    ros.start(["rosrun", "map_server", "map_server", str(tmp_path / "s.yaml")])
    ros.wait_for_topic("/map")
    done = run_saver(ros, ["-f", "t", "--occ", "70", "--free", "10"], cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    pixels = (tmp_path / "t.pgm").read_bytes()[-5:]
    expected = [254 if 0 <= v <= 10 else 0 if v >= 70 else 205 for v in served]
    assert list(pixels) == expected
    assert len(set(expected)) == 3


def test_no_map_times_out_with_an_explanation(ros, tmp_path):
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    start = time.monotonic()
    done = run_saver(ros, ["--timeout", "2"], cwd=tmp_path)
    elapsed = time.monotonic() - start
    assert done.returncode == 1
    assert "no map received from /map" in done.stderr
    assert "Is a mapper" in done.stderr
    assert "/use_sim_time is true but nothing publishes /clock" in done.stderr
    assert elapsed < 30  # wall-clock timeout even though sim time never moves
    assert list(tmp_path.glob("map.*")) == []


def test_timeout_names_other_map_topics(ros, tmp_path):
    _, yaml_path = served_map(tmp_path)
    ros.start(["rosrun", "map_server", "map_server", str(yaml_path), "map:=/slam/map"])
    ros.wait_for_topic("/slam/map")
    done = run_saver(ros, ["--timeout", "1"], cwd=tmp_path)
    assert done.returncode == 1
    assert "/slam/map" in done.stderr and "map:=/slam/map" in done.stderr


def test_bad_arguments_and_unwritable_target(ros, tmp_path):
    done = run_saver(ros, ["--occ", "0"], cwd=tmp_path)
    assert done.returncode != 0 and "between 1 and 100" in done.stderr
    done = run_saver(ros, ["--occ", "30", "--free", "40"], cwd=tmp_path)
    assert done.returncode != 0 and "smaller" in done.stderr
    _, yaml_path = served_map(tmp_path)
    ros.start(["rosrun", "map_server", "map_server", str(yaml_path)])
    ros.wait_for_topic("/map")
    # A folder that does not exist is refused before any wait, with the command that fixes it.
    done = run_saver(ros, ["-f", str(tmp_path / "missing_dir" / "map")], cwd=tmp_path)
    assert done.returncode == 2
    assert "missing_dir" in done.stderr and "mkdir -p" in done.stderr
    assert not (tmp_path / "missing_dir").exists()


def test_service_only_timeout_explains(ros, tmp_path):
    _, yaml_path = served_map(tmp_path)
    ros.start(["rosrun", "map_server", "map_server", str(yaml_path)])
    ros.wait_for_service("/static_map")
    done = run_saver(ros, ["--service", "--timeout", "1"], cwd=tmp_path)
    assert done.returncode == 1
    assert "no map received from the /dynamic_map service" in done.stderr
    assert "dynamic_map:=static_map" in done.stderr
    # The hint works: the same command with the remapping saves map_server's map.
    done = run_saver(ros, ["--service", "dynamic_map:=static_map"], cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    assert (tmp_path / "map.yaml").exists()
