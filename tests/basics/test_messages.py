"""rosmsg / rossrv show the basics types as the book prints them (chapters 3-5)."""

import subprocess

import pytest
from roskit import free_port, ros_environment

COMMANDS = {
    "Complex": ["rosmsg", "show", "Complex"],
    "basics/Complex": ["rosmsg", "show", "basics/Complex"],
    "WordCount": ["rossrv", "show", "WordCount"],
    "TimerGoal": ["rosmsg", "show", "TimerGoal"],
    "TimerActionGoal": ["rosmsg", "show", "TimerActionGoal"],
    "TimerResult": ["rosmsg", "show", "basics/TimerResult"],
    "TimerFeedback": ["rosmsg", "show", "basics/TimerFeedback"],
    "package": ["rosmsg", "package", "basics"],
}


@pytest.fixture(scope="module")
def shown():
    """Every command's output; they need no master and run side by side."""
    env = ros_environment(free_port())
    runs = {
        key: subprocess.Popen(
            cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env
        )
        for key, cmd in COMMANDS.items()
    }
    outputs = {}
    for key, run in runs.items():
        stdout, stderr = run.communicate(timeout=120)
        assert run.returncode == 0, f"{COMMANDS[key]}: {stderr}"
        outputs[key] = stdout
    return outputs


def test_rosmsg_show_complex(shown):
    assert shown["Complex"] == "[basics/Complex]:\nfloat32 real\nfloat32 imaginary\n\n"
    assert shown["basics/Complex"] == "float32 real\nfloat32 imaginary\n\n"
    # As in the book: only msg/ files are listed; the Timer* messages are generated.
    assert shown["package"] == "basics/Complex\n"


def test_rossrv_show_word_count(shown):
    assert shown["WordCount"] == "[basics/WordCount]:\nstring words\n---\nuint32 count\n\n"


def test_timer_action_messages(shown):
    assert shown["TimerGoal"] == "[basics/TimerGoal]:\nduration time_to_wait\n\n"
    assert shown["TimerActionGoal"].splitlines() == [
        "[basics/TimerActionGoal]:",
        "std_msgs/Header header",
        "  uint32 seq",
        "  time stamp",
        "  string frame_id",
        "actionlib_msgs/GoalID goal_id",
        "  time stamp",
        "  string id",
        "basics/TimerGoal goal",
        "  duration time_to_wait",
        "",
    ]
    assert shown["TimerResult"] == "duration time_elapsed\nuint32 updates_sent\n\n"
    assert shown["TimerFeedback"] == "duration time_elapsed\nduration time_remaining\n\n"
