"""Chapter 5, actions: the timer with the simple and the fancy server and client."""

import re
import shlex
import subprocess
from pathlib import Path

import pytest
from roskit import DEBIAN_PYTHON, free_port, read_jsonl, ros_environment

HERE = Path(__file__).resolve().parent
ACTION_CLOCK = HERE / "action_clock.py"
SCRIPTS = HERE.parents[1] / "catkin_ws" / "src" / "basics" / "scripts"
POLL = 0.01  # fancy_action_server.py's nap between preemption checks (its time resolution)
LAG = 0.1  # basics.timer.TICK_LAG: feedback k goes out at k + LAG seconds

FEEDBACK = re.compile(
    r"^\[Feedback\] Time elapsed: (\S+)\n\[Feedback\] Time remaining: (\S+)$", re.M
)
RESULT = re.compile(
    r"^\[Result\] State: (\d+)\n\[Result\] Status: (.*)\n"
    r"\[Result\] Time elapsed: (\S+)\n\[Result\] Updates sent: (\d+)$",
    re.M,
)


def timer_on_sim_time(
    ros, master, server="fancy_action_server.py", *clock_options, server_running=False
):
    """use_sim_time, the action's lock-step /clock (action_clock.py: it holds still until a
    goal has started, then jumps from feedback to feedback and waits for each, at the server
    and printed by fancy_client's client), then the server, which takes goals once it has the
    clock. With a server (started here, or `server_running`), returns once the clock hears
    it, so that a result sent at once (an abort) cannot go out before the clock listens."""
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    out = ros.workdir / f"action-clock-{ros._log_index + 1:02d}.jsonl"
    client_out = out.with_suffix(".client-stdout")
    cmd = [DEBIAN_PYTHON, str(ACTION_CLOCK), "--out", str(out), "--poll", str(POLL)]
    cmd += ["--client-out", str(client_out)]
    clock = ros.start(cmd + [str(o) for o in clock_options], name="action_clock")
    clock.client_out = client_out
    if server:
        ros.start(["rosrun", "basics", server])
        master.wait_for_topic("timer/result")
    if server or server_running:
        ready = Path(f"{out}.ready")
        ros.wait_for(ready.exists, timeout=90, what="the action clock to hear the server")
    return clock


def wait_for_client(ros, client, clock, timeout=180):
    """Until the client exits; fails at once, with the clock's own message, if the clock gave
    up first (it waits 60 s for what is due)."""
    ros.wait_for(
        lambda: client.poll() is not None or clock.poll() not in (None, 0),
        timeout=timeout,
        what="the action client",
    )
    assert clock.poll() in (None, 0), ros.output(clock)
    return client.returncode


def fancy_client(ros, clock, *args):
    """Run fancy_action_client.py; return (feedback [(elapsed, remaining)], result tuple). Its
    stdout goes where the clock reads it: the clock moves on from a feedback only once the
    client has printed it, so the result cannot overtake feedback the client has not handled
    yet (actionlib's client drops that), however long a loaded machine stalls the client."""
    cmd = shlex.join(["rosrun", "basics", "fancy_action_client.py", *args])
    client = ros.start(f"exec {cmd} > {shlex.quote(str(clock.client_out))}", name="client")
    code = wait_for_client(ros, client, clock)
    assert code == 0, ros.output(client) + clock.client_out.read_text()
    out = clock.client_out.read_text()
    assert clock.wait(timeout=120) == 0, ros.output(clock)
    feedback = [(float(e), float(r)) for e, r in FEEDBACK.findall(out)]
    (state, status, elapsed, updates), *_ = RESULT.findall(out)
    return feedback, (int(state), status, float(elapsed), int(updates))


def server_feedback(clock):
    """The server's feedback [(elapsed, remaining)] as the action clock recorded it."""
    records = read_jsonl(clock.args[clock.args.index("--out") + 1])
    return [(r["elapsed"], r["remaining"]) for r in records if r["topic"] == "/timer/feedback"]


def as_printed(feedback):
    """(elapsed, remaining) pairs to the client's printed precision."""
    return [(round(e, 6), round(r, 6)) for e, r in feedback]


def assert_client_printed_all(printed, sent):
    """The client prints every feedback the server sent, in order: the clock waits for each
    to be printed before the result can be due."""
    assert as_printed(printed) == as_printed(sent)


def assert_feedback_once_a_second(feedback, goal):
    """Feedback k at k + LAG s (k >= 1), at most one server nap late; remaining = goal - elapsed."""
    for k, (e, r) in enumerate(feedback):
        due = k + LAG if k else 0.0
        assert due - 1e-6 <= e <= due + POLL + 1e-6, (k, e)
        assert e + r == pytest.approx(goal, abs=1e-6)


def test_five_second_goal_succeeds_with_five_feedbacks(ros, master):
    clock = timer_on_sim_time(ros, master, "fancy_action_server.py", "--goal", 5)
    printed, (state, status, elapsed, updates) = fancy_client(ros, clock)
    assert (state, status, updates) == (3, "Timer completed successfully", 5)
    assert 5.0 - 1e-6 <= elapsed <= 5.0 + POLL + 1e-6
    feedback = server_feedback(clock)
    assert len(feedback) == 5
    assert_feedback_once_a_second(feedback, 5.0)
    assert_client_printed_all(printed, feedback)


def test_cancel_after_three_seconds_preempts(ros, master):
    options = ["--goal", 5, "--cancel-at", 3]
    clock = timer_on_sim_time(ros, master, "fancy_action_server.py", *options)
    printed, (state, status, elapsed, updates) = fancy_client(ros, clock, "--preempt-after", "3")
    assert (state, status) == (2, "Timer preempted")
    feedback = server_feedback(clock)
    # The cancel goes out at 3 s of sim time; the server notices it by the end of its nap,
    # well before feedback 3 would go out at 3 + LAG.
    assert 3.0 - 1e-6 <= elapsed <= 3.0 + 2 * POLL + 1e-6
    assert updates == 3 and len(feedback) == 3
    assert_feedback_once_a_second(feedback, 5.0)
    assert_client_printed_all(printed, feedback)


def test_too_long_and_negative_goals_abort_at_once(ros, master):
    clock = timer_on_sim_time(ros, master, "fancy_action_server.py", "--goal", 500)
    feedback, (state, status, elapsed, updates) = fancy_client(ros, clock, "--duration", "500")
    assert (state, status, updates, feedback) == (4, "Timer aborted due to too-long wait", 0, [])
    assert elapsed == 0.0  # the clock held still: the server did not wait at all

    clock = timer_on_sim_time(ros, master, None, "--goal", -2, "--start", 2000, server_running=True)
    feedback, (state, status, elapsed, updates) = fancy_client(ros, clock, "--duration", "-2")
    assert (state, updates, feedback, elapsed) == (4, 0, [], 0.0)
    assert status == "Timer aborted due to negative wait (-2.000000 s)"


def test_timer_runs_on_sim_time(ros, master):
    """Under /use_sim_time both nodes follow /clock: a 50 s goal's feedback comes once a
    simulated second and it ends after 50 simulated seconds, though the clock jumps from
    one feedback to the next: a wall-clock server could not match them."""
    clock = timer_on_sim_time(ros, master, "fancy_action_server.py", "--goal", 50)
    printed, (state, _, elapsed, updates) = fancy_client(ros, clock, "--duration", "50")
    assert (state, updates) == (3, 50)
    assert 50.0 - 1e-6 <= elapsed <= 50.0 + POLL + 1e-6
    feedback = server_feedback(clock)
    assert len(feedback) == 50
    assert_feedback_once_a_second(feedback, 50.0)
    assert_client_printed_all(printed, feedback)


def test_simple_client_waits_for_the_server_then_gets_five_seconds(ros, master):
    # The clock runs until the client has given up its first 1 s wait for the server, then
    # holds until the goal has started and jumps to its end.
    hold = ros.workdir / "hold-the-clock"
    clock = timer_on_sim_time(ros, master, None, "--goal", 5, "--simple", "--free-until", hold)
    client = ros.start(["rosrun", "basics", "simple_action_client.py"])
    ros.wait_for(
        lambda: "waiting for the action server /timer" in ros.output(client),
        timeout=60,
        what="the client to wait",
    )
    hold.touch()
    assert client.poll() is None
    ros.start(["rosrun", "basics", "simple_action_server.py"])
    assert wait_for_client(ros, client, clock) == 0, ros.output(client)
    assert clock.wait(timeout=120) == 0, ros.output(clock)
    elapsed = float(re.search(r"^Time elapsed: (\S+)$", ros.output(client), re.M).group(1))
    assert 5.0 - 1e-6 <= elapsed <= 5.0 + 1e-6  # the clock held still at its end


def test_simple_server_aborts_a_negative_goal(ros, master):
    clock = timer_on_sim_time(ros, master, "simple_action_server.py", "--goal", -1, "--simple")
    feedback, (state, status, _, updates) = fancy_client(ros, clock, "--duration", "-1")
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
