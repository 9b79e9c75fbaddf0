"""Reliability matrix for the nodes' parameters and input files: a value a node cannot work
with (out of range, not finite, of the wrong type) ends it at start-up with exit code 2 and
one line naming the parameter and its value; a map or waypoint file that cannot be used ends
map_server / patrol.py with one line naming the file and the fault. Each row: (package,
node, arguments, exit code, texts the output must hold). The rows share one roscore; each
node runs under its own name, so no row sees another's private parameters."""

import pytest

# amcl_lite (C++), move_base_lite, the explorer, and the book's nodes of chapters 7-8.
PARAM_CASES = {
    "amcl min_particles 0": ("amcl_lite", "amcl", ["_min_particles:=0"], ["min_particles = 0"]),
    "amcl max below min": (
        "amcl_lite",
        "amcl",
        ["_min_particles:=500", "_max_particles:=100"],
        ["max_particles"],
    ),
    "amcl odom_alpha1 -1": ("amcl_lite", "amcl", ["_odom_alpha1:=-1"], ["odom_alpha1 = -1"]),
    "amcl laser_max_beams 0": (
        "amcl_lite",
        "amcl",
        ["_laser_max_beams:=0"],
        ["laser_max_beams = 0"],
    ),
    "amcl update_min_d nan": ("amcl_lite", "amcl", ["_update_min_d:=nan"], ["update_min_d"]),
    "amcl odom model omni": ("amcl_lite", "amcl", ["_odom_model_type:=omni"], ["omni"]),
    "amcl laser model beam": ("amcl_lite", "amcl", ["_laser_model_type:=beam"], ["beam"]),
    "amcl recovery_alpha_slow 2": (
        "amcl_lite",
        "amcl",
        ["_recovery_alpha_slow:=2"],
        ["recovery_alpha_slow = 2"],
    ),
    "amcl kld_err 0": ("amcl_lite", "amcl", ["_kld_err:=0"], ["kld_err = 0"]),
    "amcl laser_z_hit not a number": (
        "amcl_lite",
        "amcl",
        ["_laser_z_hit:=abc"],
        ["laser_z_hit = abc", "must be a number"],
    ),
    "amcl use_map_topic not a bool": (
        "amcl_lite",
        "amcl",
        ["_use_map_topic:=maybe"],
        ["use_map_topic = maybe", "true or false"],
    ),
    "amcl transform_tolerance nan": (
        "amcl_lite",
        "amcl",
        ["_transform_tolerance:=nan"],
        ["transform_tolerance = nan", "a finite number"],
    ),
    "amcl transform_tolerance -1": (
        "amcl_lite",
        "amcl",
        ["_transform_tolerance:=-1"],
        ["transform_tolerance = -1", "seconds >= 0"],
    ),
    "amcl max_particles 1e9": (
        "amcl_lite",
        "amcl",
        ["_max_particles:=1000000000"],
        ["max_particles = 1e+09", "<= 1000000"],
    ),
    "amcl resample_interval 0": (
        "amcl_lite",
        "amcl",
        ["_resample_interval:=0"],
        ["resample_interval = 0", ">= 1"],
    ),
    "amcl kld_z 0.2": ("amcl_lite", "amcl", ["_kld_z:=0.2"], ["kld_z = 0.2", "in (0.5, 1)"]),
    "amcl initial_pose_x inf": (
        "amcl_lite",
        "amcl",
        ["_initial_pose_x:=inf"],
        ["initial_pose_x = inf", "a finite number"],
    ),
    "move_base max_recoveries 2.5": (
        "move_base_lite",
        "move_base.py",
        ["_max_recoveries:=2.5"],
        ["~max_recoveries must be a whole number, got 2.5"],
    ),
    "move_base max_recoveries -1": (
        "move_base_lite",
        "move_base.py",
        ["_max_recoveries:=-1"],
        ["~max_recoveries must be >= 0, got -1"],
    ),
    "explorer control_rate 0": (
        "explorer",
        "explorer.py",
        ["_control_rate:=0"],
        ["~control_rate must be > 0, got 0"],
    ),
    "explorer replan_period -1": (
        "explorer",
        "explorer.py",
        ["_replan_period:=-1"],
        ["~replan_period must be > 0, got -1"],
    ),
    "latched_publisher count 0": (
        "basics",
        "latched_publisher.py",
        ["_count:=0"],
        ["~count must be a positive integer, got 0"],
    ),
    "service_server mode nosuch": (
        "basics",
        "service_server.py",
        ["_mode:=nosuch"],
        ["~mode must be one of response, value, list, tuple, dict, got 'nosuch'"],
    ),
    "wander min_range 0": (
        "wanderbot",
        "wander.py",
        ["_min_range:=0"],
        ["~min_range must be > 0, got 0"],
    ),
    "move_base robot_radius -1": (
        "move_base_lite",
        "move_base.py",
        ["_robot_radius:=-1"],
        ["~robot_radius must be > 0, got -1"],
    ),
    "move_base inflation below the robot": (
        "move_base_lite",
        "move_base.py",
        ["_inflation_radius:=0.01"],
        ["~inflation_radius must be >= ~robot_radius"],
    ),
    "move_base max_vel_x nan": (
        "move_base_lite",
        "move_base.py",
        ["_max_vel_x:=nan"],
        ["~max_vel_x", "nan"],
    ),
    "move_base xy_goal_tolerance -1": (
        "move_base_lite",
        "move_base.py",
        ["_xy_goal_tolerance:=-1"],
        ["~xy_goal_tolerance must be > 0"],
    ),
    "move_base controller_frequency 0": (
        "move_base_lite",
        "move_base.py",
        ["_controller_frequency:=0"],
        ["~controller_frequency must be > 0"],
    ),
    "move_base max_rot_vel text": (
        "move_base_lite",
        "move_base.py",
        ["_max_rot_vel:=fast"],
        ["~max_rot_vel", "fast"],
    ),
    "explorer robot_radius -1": (
        "explorer",
        "explorer.py",
        ["_robot_radius:=-1"],
        ["~robot_radius must be > 0, got -1"],
    ),
    "explorer min_frontier_size nan": (
        "explorer",
        "explorer.py",
        ["_min_frontier_size:=nan"],
        ["~min_frontier_size", "nan"],
    ),
    "explorer max_linear 0": (
        "explorer",
        "explorer.py",
        ["_max_linear:=0"],
        ["~max_linear must be > 0"],
    ),
    "explorer inflation below the robot": (
        "explorer",
        "explorer.py",
        ["_inflation_radius:=0.1"],
        ["~inflation_radius must be >= ~robot_radius"],
    ),
    "slam_gmapping delta not a number": (
        "gmapping_lite",
        "slam_gmapping",
        ["_delta:=abc"],
        ["~delta is 'abc': it must be a number"],
    ),
    "wander forward_speed nan": (
        "wanderbot",
        "wander.py",
        ["_forward_speed:=nan"],
        ["~forward_speed", "nan"],
    ),
    "wander spin_time 0": ("wanderbot", "wander.py", ["_spin_time:=0"], ["~spin_time", "> 0"]),
    "ramps linear_scale nan": (
        "teleop_bot",
        "keys_to_twist_with_ramps.py",
        ["_linear_scale:=nan"],
        ["~linear_scale", "nan"],
    ),
    "ramps linear_accel -1": (
        "teleop_bot",
        "keys_to_twist_with_ramps.py",
        ["_linear_accel:=-1"],
        ["~linear_accel", "> 0"],
    ),
    "parameterized linear_scale text": (
        "teleop_bot",
        "keys_to_twist_parameterized.py",
        ["_linear_scale:=abc"],
        ["~linear_scale", "abc"],
    ),
}


def node_name(case):
    """A ROS node name of its own for each row, so no row sees another's parameters."""
    return "row_" + "".join(c if c.isalnum() else "_" for c in case)


@pytest.mark.parametrize("case", sorted(PARAM_CASES))
def test_node_refuses_a_bad_parameter_at_start_up(shared_ros, case):
    package, node, args, texts = PARAM_CASES[case]
    name = node_name(case)
    done = shared_ros.run(["rosrun", package, node, *args, f"__name:={name}"], check=False)
    out = done.stdout + done.stderr
    assert done.returncode == 2, out
    assert all(text in out for text in texts), out


# Values rosrun's _NAME:=VALUE cannot give (an empty string), set on the master first.
PRESET_CASES = {
    "amcl empty odom_frame_id": (
        "amcl_lite",
        "amcl",
        {"odom_frame_id": ""},
        ["parameter odom_frame_id is empty", "_odom_frame_id:=FRAME"],
    ),
    "amcl empty base_frame_id": (
        "amcl_lite",
        "amcl",
        {"base_frame_id": ""},
        ["parameter base_frame_id is empty", "_base_frame_id:=FRAME"],
    ),
}


@pytest.mark.parametrize("case", sorted(PRESET_CASES))
def test_node_refuses_a_bad_preset_parameter_at_start_up(shared_ros, case):
    package, node, params, texts = PRESET_CASES[case]
    name = node_name(case)
    for param, value in params.items():
        shared_ros.master().setParam("/test_node_params", f"/{name}/{param}", value)
    done = shared_ros.run(["rosrun", package, node, f"__name:={name}"], check=False)
    out = done.stdout + done.stderr
    assert done.returncode == 2, out
    assert all(text in out for text in texts), out


MAP_YAML = (
    "image: {image}\nresolution: {resolution}\norigin: {origin}\nnegate: 0\n"
    "occupied_thresh: {occ}\nfree_thresh: {free}\n"
)
GOOD = {
    "image": "m.pgm",
    "resolution": "0.05",
    "origin": "[0, 0, 0]",
    "occ": "0.65",
    "free": "0.196",
}
# map_server given a map description it cannot serve: (fields over GOOD, texts).
MAP_CASES = {
    "negative resolution": ({"resolution": "-0.05"}, ["'resolution' must be positive"]),
    "zero resolution": ({"resolution": "0"}, ["'resolution' must be positive"]),
    "nan origin": ({"origin": "[.nan, 0, 0]"}, ["'origin' must be finite"]),
    "origin of two numbers": ({"origin": "[0, 0]"}, ["origin"]),
    "occupied_thresh above 1": ({"occ": "1.5"}, ["'occupied_thresh' must be between 0 and 1"]),
    "free above occupied": ({"occ": "0.1", "free": "0.5"}, ["free_thresh (0.5) must be smaller"]),
    "image missing": ({"image": "missing.pgm"}, ["missing.pgm: map image not found"]),
    "image truncated": ({"image": "trunc.pgm"}, ["truncated pixel data"]),
    "image claims 10^10 pixels": ({"image": "huge.pgm"}, ["huge.pgm", "100000x100000"]),
    "image is not a picture": ({"image": "text.pgm"}, ["text.pgm"]),
}


def write_map_files(folder):
    (folder / "m.pgm").write_bytes(b"P5\n10 10\n255\n" + bytes(100))
    (folder / "trunc.pgm").write_bytes(b"P5\n10 10\n255\nab")
    (folder / "huge.pgm").write_bytes(b"P5\n100000 100000\n255\n")
    (folder / "text.pgm").write_text("not an image at all\n")


@pytest.mark.parametrize("case", sorted(MAP_CASES))
def test_map_server_refuses_a_map_it_cannot_serve(shared_ros, tmp_path, case):
    fields, texts = MAP_CASES[case]
    write_map_files(tmp_path)
    yaml_path = tmp_path / "map.yaml"
    yaml_path.write_text(MAP_YAML.format(**{**GOOD, **fields}))
    name = node_name(case)
    cmd = ["rosrun", "map_server", "map_server", str(yaml_path), f"__name:={name}"]
    done = shared_ros.run(cmd, check=False)
    out = done.stdout + done.stderr
    assert done.returncode == 1, out
    assert "map_server: cannot load the map" in out and all(t in out for t in texts), out


# patrol.py's waypoint files and arguments: refused before it talks to move_base.
PATROL_CASES = {
    "waypoint without numbers": ("- {x: abc, y: 3}\n", [], 1, ["waypoint 0 must have numbers"]),
    "empty waypoint list": ("waypoints: []\n", [], 1, ["expected a non-empty list"]),
    "nan waypoint": ("- {x: .nan, y: 0}\n", [], 1, ["waypoint 0 has a non-finite value"]),
    "waypoints not yaml": ("x: [1, 2\n", [], 1, ["waypoints.yaml"]),
    "negative loops": (None, ["--loops", "-1"], 2, ["must be 0 (patrol until Ctrl-C) or more"]),
    "loops not a number": (None, ["--loops", "abc"], 2, ["'abc' is not a whole number"]),
}


@pytest.mark.parametrize("case", sorted(PATROL_CASES))
def test_patrol_refuses_bad_waypoints_and_arguments(shared_ros, tmp_path, case):
    text, args, code, texts = PATROL_CASES[case]
    if text is not None:
        (tmp_path / "waypoints.yaml").write_text(text)
        args = ["--waypoints", str(tmp_path / "waypoints.yaml")]
    done = shared_ros.run(["rosrun", "patrolbot", "patrol.py", *args], check=False)
    out = done.stdout + done.stderr
    assert done.returncode == code, out
    assert all(t in out for t in texts), out
