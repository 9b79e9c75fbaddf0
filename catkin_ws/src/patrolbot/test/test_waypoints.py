import math

import pytest
from patrolbot.waypoints import WaypointError, load_waypoints


def test_yaml_waypoints_become_the_books_position_quaternion_pairs(tmp_path):
    path = tmp_path / "w.yaml"
    path.write_text("waypoints:\n  - {x: 1, y: 2, yaw: 1.5707963}\n  - {x: 3, y: 4}\n")
    poses = load_waypoints(path)
    assert poses[0][0] == (1.0, 2.0, 0.0)
    assert poses[0][1][2] == pytest.approx(math.sqrt(0.5))
    assert poses[1][1] == (0.0, 0.0, 0.0, 1.0)


def test_bad_files_are_named(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("waypoints:\n  - {x: 1}\n")
    with pytest.raises(WaypointError, match="bad.yaml: waypoint 0"):
        load_waypoints(path)
    with pytest.raises(WaypointError, match="missing.yaml"):
        load_waypoints(tmp_path / "missing.yaml")


def test_a_key_given_twice_in_a_waypoint_is_refused(tmp_path):
    path = tmp_path / "twice.yaml"
    path.write_text("waypoints:\n  - {x: 1, y: 2}\n  - {x: 3, y: 4, x: 5}\n")
    with pytest.raises(WaypointError, match=r"twice.yaml: key 'x' given twice"):
        load_waypoints(path)
