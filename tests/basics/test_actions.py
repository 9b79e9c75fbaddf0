"""Chapter 5, actions: the timer with the simple and the fancy server and client."""

import re
import subprocess
import time
from pathlib import Path

import pytest
from roskit import DEBIAN_PYTHON, free_port, ros_environment

SIM_CLOCK = Path(__file__).resolve().parent / "sim_clock.py"
SCRIPTS = Path(__file__).resolve().parents[2] / "catkin_ws" / "src" / "basics" / "scripts"

FEEDBACK = re.compile(
    r"^\[Feedback\] Time elapsed: (\S+)\n\[Feedback\] Time remaining: (\S+)$", re.M
)
RESULT = re.compile(
    r"^\[Result\] State: (\d+)\n\[Result\] Status: (.*)\n"
    r"\[Result\] Time elapsed: (\S+)\n\[Result\] Updates sent: (\d+)$",
    re.M,
)


def fancy_client(ros, *args):
    """Run fancy_action_client.py; return (feedback [(elapsed, remaining)], result tuple)."""
    out = ros.run(["rosrun", "basics", "fancy_action_client.py", *args], timeout=60).stdout
    feedback = [(float(e), float(r)) for e, r in FEEDBACK.findall(out)]
    (state, status, elapsed, updates), *_ = RESULT.findall(out)
    return feedback, (int(state), status, float(elapsed), int(updates))


# The fancy server, shared by the tests that use `shared_graph` (goals run one at a time).
SHARED_NODES = [["rosrun", "basics", "fancy_action_server.py"]]
SHARED_TOPICS = ["timer/result"]


def test_five_second_goal_succeeds_with_five_feedbacks(shared_graph):
    feedback, (state, status, elapsed, updates) = fancy_client(shared_graph)
    assert (state, status, updates) == (3, "Timer completed successfully", 5)
    assert elapsed == pytest.approx(5.0, abs=0.25)
    assert len(feedback) == 5
    for k, (e, r) in enumerate(feedback):
        assert e == pytest.approx(k, abs=0.3)  # once a second
        assert e + r == pytest.approx(5.0, abs=1e-3)


def test_cancel_after_three_seconds_preempts(shared_graph):
    feedback, (state, status, elapsed, updates) = fancy_client(shared_graph, "--preempt-after", "3")
    assert (state, status) == (2, "Timer preempted")
    assert elapsed == pytest.approx(3.0, abs=0.25)
    assert updates == 3 and len(feedback) == 3


def test_too_long_and_negative_goals_abort_at_once(shared_graph):
    started = time.monotonic()
    feedback, (state, status, elapsed, updates) = fancy_client(shared_graph, "--duration", "500")
    assert (state, status, updates, feedback) == (4, "Timer aborted due to too-long wait", 0, [])
    assert elapsed < 0.5
    assert time.monotonic() - started < 30  # not 500 s

    feedback, (state, status, _, updates) = fancy_client(shared_graph, "--duration", "-2")
    assert (state, updates, feedback) == (4, 0, [])
    assert status == "Timer aborted due to negative wait (-2.000000 s)"


def test_timer_runs_on_sim_time(ros, master):
    """Under /use_sim_time both nodes follow /clock: a 50 s goal at 20x takes about 2.5 s."""
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    ros.start([DEBIAN_PYTHON, str(SIM_CLOCK), "--start", "1000", "--step", "0.2"])
    master.wait_for_topic("clock")
    ros.start(["rosrun", "basics", "fancy_action_server.py"])
    master.wait_for_topic("timer/result")
    started = time.monotonic()
    feedback, (state, _, elapsed, updates) = fancy_client(ros, "--duration", "50")
    wall = time.monotonic() - started
    assert (state, updates, len(feedback)) == (3, 50, 50)
    assert elapsed == pytest.approx(50.0, abs=0.5)
    # Once a simulated second (the clock moves in 0.2 s steps).
    assert [round(e) for e, _ in feedback] == list(range(50))
    assert wall < 45, f"{wall:.1f} s of wall time for 50 s of sim time: /clock not followed"


def test_simple_client_waits_for_the_server_then_gets_five_seconds(ros):
    client = ros.start(["rosrun", "basics", "simple_action_client.py"])
    ros.wait_for(
        lambda: "waiting for the action server /timer" in ros.output(client),
        timeout=60,
        what="the client to wait",
    )
    assert client.poll() is None
    ros.start(["rosrun", "basics", "simple_action_server.py"])
    assert client.wait(timeout=60) == 0
    elapsed = float(re.search(r"^Time elapsed: (\S+)$", ros.output(client), re.M).group(1))
    assert 5.0 <= elapsed < 5.25


def test_simple_server_aborts_a_negative_goal(ros, master):
    ros.start(["rosrun", "basics", "simple_action_server.py"])
    master.wait_for_topic("timer/result")
    feedback, (state, status, _, updates) = fancy_client(ros, "--duration", "-1")
    assert (state, updates, feedback) == (4, 0, [])
    assert status.startswith("Timer aborted due to negative wait")


BAD_ARGUMENTS = [
    (["--duration", "abc"], "argument --duration: not a number of seconds: 'abc'"),
    (["--duration", "nan"], "argument --duration: seconds must be finite"),
    (["--duration", "1e12"], "argument --duration: seconds must be finite"),
    (["--preempt-after", "-1"], "argument --preempt-after: a delay cannot be negative"),
    (["--preempt-after", "soon"], "argument --preempt-after: not a number of seconds"),
]


def test_bad_client_arguments_are_usage_errors():
    env = ros_environment(free_port())  # no master: the client fails before init_node
    runs = [
        subprocess.Popen(
            [str(SCRIPTS / "fancy_action_client.py"), *args],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            env=env,
        )
        for args, _ in BAD_ARGUMENTS
    ]
    for run, (args, message) in zip(runs, BAD_ARGUMENTS, strict=True):
        _, stderr = run.communicate(timeout=60)
        assert run.returncode == 2, args
        assert "usage: fancy_action_client.py" in stderr
        assert message in stderr
