"""sim_params: the list of simulator parameters equals the names the node's C++ reads."""

import re
from pathlib import Path

from bullet_turtlebot.sim_params import (
    INTERNAL_PARAMS,
    SIMULATOR_PARAMS,
    unknown_sim_param_error,
)

NODE = Path(__file__).resolve().parent.parent / "src" / "node"
# checked_number(pnh, "x", ...), checked_int(pnh_, ...), param(pnh_, "start_paused", ...),
# pnh.param("odom_noise", ...): every way the node reads a private parameter by name.
READ = re.compile(r'(?:checked_\w+|param)\(\s*pnh_?,\s*"(\w+)"|pnh_?\.param\(\s*"(\w+)"')


def names_the_node_reads():
    names = set()
    for source in ("simulator_node.cpp", "ros_sim.cpp"):
        for match in READ.finditer((NODE / source).read_text()):
            names.add(match.group(1) or match.group(2))
    return names


def test_the_list_is_what_the_node_reads():
    assert len(SIMULATOR_PARAMS) == len(set(SIMULATOR_PARAMS))
    assert set(SIMULATOR_PARAMS) | set(INTERNAL_PARAMS) == names_the_node_reads()


def test_unknown_names_get_an_error_listing_the_known_ones():
    assert unknown_sim_param_error("scan_fov_deg") is None
    message = unknown_sim_param_error("scan_fov")
    assert "unknown simulator parameter 'scan_fov'" in message
    assert "scan_fov_deg" in message and "range_max" in message
    assert unknown_sim_param_error("use_sim_time_before_launch") is not None
