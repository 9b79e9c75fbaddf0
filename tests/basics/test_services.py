"""Chapter 4, services: word_count from rosservice and service_client.py, every return style."""

import re
import subprocess
import time

import pytest
from roskit import free_port, ros_environment


def call_word_count(ros, service, words):
    done = ros.run(["rosservice", "call", service, words])
    return int(re.fullmatch(r"count: (\d+)\s*", done.stdout).group(1))


# The book's four return styles, chosen with --mode or ~mode, each server in its own
# namespace, next to the default server; shared by the tests that use `shared_graph`.
MODES = {
    "response": ["--mode", "response"],
    "value": ["--mode", "value"],
    "list": ["_mode:=list"],
    "tuple": ["--mode", "tuple"],
    "dict": ["_mode:=dict"],
}
SHARED_NODES = [["rosrun", "basics", "service_server.py"]] + [
    ["rosrun", "basics", "service_server.py", *args, f"__ns:={mode}"]
    for mode, args in MODES.items()
]
SHARED_SERVICES = ["word_count"] + [f"/{mode}/word_count" for mode in MODES]


def test_word_count_from_rosservice_and_service_client(shared_graph):
    ros = shared_graph
    info = ros.run(["rosservice", "info", "word_count"]).stdout
    assert "Node: /service_server" in info
    assert "Type: basics/WordCount" in info
    assert "Args: words" in info

    assert ros.run(["rosservice", "call", "word_count", "one two three"]).stdout == "count: 3\n"
    assert call_word_count(ros, "word_count", "") == 0

    quoted = ros.run(["rosrun", "basics", "service_client.py", "these are some words"])
    assert quoted.stdout == "these are some words -> 4\n"
    unquoted = ros.run(["rosrun", "basics", "service_client.py", "these", "are", "some", "words"])
    assert unquoted.stdout == "these are some words -> 4\n"

    many = ["word"] * 100_000  # about 500 kB of request
    done = ros.run(["rosrun", "basics", "service_client.py", *many], timeout=60)
    assert done.stdout.endswith(" -> 100000\n")


@pytest.mark.parametrize("mode", MODES)
def test_every_way_of_returning_a_value(shared_graph, mode):
    assert call_word_count(shared_graph, f"/{mode}/word_count", f"style {mode} of returning") == 4


def test_client_waits_for_a_late_server(ros):
    client = ros.start(["rosrun", "basics", "service_client.py", "these are some words"])
    ros.wait_for(lambda: "waiting for the service" in ros.output(client), 60, "client waiting")
    time.sleep(1.0)
    assert client.poll() is None
    ros.start(["rosrun", "basics", "service_server.py"])
    assert client.wait(timeout=60) == 0
    assert ros.output(client).endswith("these are some words -> 4\n")


def test_bad_return_mode_is_a_usage_error():
    env = ros_environment(free_port())  # no master needed: it fails before init_node
    done = subprocess.run(
        ["rosrun", "basics", "service_server.py", "--mode", "xml"],
        capture_output=True,
        text=True,
        env=env,
        timeout=30,
    )
    assert done.returncode == 2
    assert "invalid choice: 'xml'" in done.stderr
