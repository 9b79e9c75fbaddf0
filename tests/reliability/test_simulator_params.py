"""Reliability matrix for the simulator's parameters: a value of the wrong type, not finite,
or beyond what the simulator can honour ends it at start-up with exit code 2 and one line
naming the parameter, the value and what is allowed; no simulator quietly runs with nonsense.
Each row: private parameters given to `rosrun bullet_turtlebot simulator`, and the parameter
the error must name. One roscore serves every row; each row clears the simulator's private
parameters first."""

import pytest

CASES = {
    "speed not a number": ({"speed": "abc"}, "speed"),
    "speed negative": ({"speed": "-2"}, "speed"),
    "start_time beyond ROS time": ({"start_time": "1e12"}, "start_time"),
    "start_time nan": ({"start_time": "nan"}, "start_time"),
    "scan_rate negative": ({"scan_rate": "-5"}, "scan_rate"),
    "scan_rate above physics": ({"scan_rate": "1000"}, "scan_rate"),
    "camera_rate inf": ({"camera_rate": "inf"}, "camera_rate"),
    "scan_fov_deg 720": ({"scan_fov_deg": "720"}, "scan_fov_deg"),
    "scan_samples 0": ({"scan_samples": "0"}, "scan_samples"),
    "scan_samples not whole": ({"scan_samples": "6.5"}, "scan_samples"),
    "range_max negative": ({"range_max": "-1"}, "range_max"),
    "range_min above range_max": ({"range_min": "5", "range_max": "4"}, "range_min"),
    "camera too large": ({"camera_width": "100000"}, "camera_width"),
    "max_linear negative": ({"max_linear": "-1"}, "max_linear"),
    "watchdog negative": ({"watchdog": "-1"}, "watchdog"),
    "physics_rate 1": ({"physics_rate": "1"}, "physics_rate"),
    "x huge": ({"x": "1e300"}, "/simulator/x"),
    "odometry noise 5": ({"odom_linear_noise": "5"}, "odom_linear_noise"),
    "seed negative": ({"seed": "-3"}, "seed"),
    "world a number": ({"world": "123"}, "/simulator/world is '123', not a name"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_simulator_parameter_is_refused_with_its_name(shared_ros, case):
    params, named = CASES[case]
    # rosrun's private parameters stay on the master: each row starts from none.
    shared_ros.master().deleteParam("/test_simulator_params", "/simulator")
    cmd = ["rosrun", "bullet_turtlebot", "simulator", "_world:=playground"]
    cmd += [f"_{name}:={value}" for name, value in params.items()]
    done = shared_ros.run(cmd, check=False, timeout=120)
    output = done.stdout + done.stderr
    assert done.returncode == 2, output
    line = next(line for line in output.splitlines() if line.startswith("simulator: "))
    assert named in line and "it must be" in line, line
    assert ":=VALUE" in line  # and says how to set it
