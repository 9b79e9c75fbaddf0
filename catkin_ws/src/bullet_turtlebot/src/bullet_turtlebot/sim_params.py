"""The simulator node's private parameters, by name: what `mapping_demo --sim-param NAME=VALUE`
may set. The node reads them in src/node/simulator_node.cpp (read_base_parameters, world) and
src/node/ros_sim.cpp (RosSimulator::load_parameters), which check each value's range;
test_sim_params.py keeps this list equal to the names those files read."""

SIMULATOR_PARAMS = (
    # simulator_node.cpp: the world, the base, odometry and the start pose
    "world",
    "worlds_dir",
    "seed",
    "odom_noise",
    "odom_linear_noise",
    "odom_angular_noise",
    "odom_angular_per_linear_noise",
    "odom_yaw_scale_error",
    "watchdog",
    "max_linear",
    "max_angular",
    "accel_linear",
    "accel_angular",
    "physics_rate",
    "x",
    "y",
    "yaw",
    # ros_sim.cpp: time, rates, the laser, the camera, command limits
    "speed",
    "wait_for_commands",
    "start_paused",
    "start_time",
    "odom_rate",
    "scan_rate",
    "camera_rate",
    "static_tf_rate",
    "publish_static_tf",
    "scan_samples",
    "scan_fov_deg",
    "range_max",
    "range_min",
    "sensor_noise",
    "range_noise",
    "range_noise_quadratic",
    "camera_width",
    "camera_height",
    "huge_linear",
    "huge_angular",
)

# Read by the node but set by simulator.launch itself (roslaunch's view of /use_sim_time
# before the launch), not a user's setting.
INTERNAL_PARAMS = ("use_sim_time_before_launch",)


def unknown_sim_param_error(name):
    """The error for a --sim-param NAME the simulator does not read (else None)."""
    if name in SIMULATOR_PARAMS:
        return None
    return f"unknown simulator parameter {name!r}; the simulator reads: " + ", ".join(
        sorted(SIMULATOR_PARAMS)
    )
