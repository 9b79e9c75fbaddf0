"""Chapter 4, services: word_count from rosservice and service_client.py, every return style."""

import re
import subprocess
import time

from roskit import free_port, ros_environment


def call_word_count(ros, service, words):
    done = ros.run(["rosservice", "call", service, words], timeout=30)
    return int(re.fullmatch(r"count: (\d+)\s*", done.stdout).group(1))


def test_word_count_from_rosservice_and_service_client(ros, master):
    ros.start(["rosrun", "basics", "service_server.py"])
    master.wait_for_service("word_count")
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


def test_every_way_of_returning_a_value(ros, master):
    """The book's four return styles, chosen with --mode or ~mode, in their own namespaces."""
    modes = {
        "response": ["--mode", "response"],
        "value": ["--mode", "value"],
        "list": ["_mode:=list"],
        "tuple": ["--mode", "tuple"],
        "dict": ["_mode:=dict"],
    }
    for mode, args in modes.items():
        ros.start(["rosrun", "basics", "service_server.py", *args, f"__ns:={mode}"])
    for mode in modes:
        master.wait_for_service(f"/{mode}/word_count")
        assert call_word_count(ros, f"/{mode}/word_count", f"style {mode} of returning") == 4


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
