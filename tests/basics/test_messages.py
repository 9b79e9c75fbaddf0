"""rosmsg / rossrv show the basics types as the book prints them (chapters 3-5)."""

import subprocess

from roskit import free_port, ros_environment


def show(*cmd):
    done = subprocess.run(
        list(cmd), capture_output=True, text=True, env=ros_environment(free_port()), timeout=60
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_rosmsg_show_complex():
    assert show("rosmsg", "show", "Complex") == (
        "[basics/Complex]:\nfloat32 real\nfloat32 imaginary\n\n"
    )
    assert show("rosmsg", "show", "basics/Complex") == "float32 real\nfloat32 imaginary\n\n"


def test_rossrv_show_word_count():
    assert show("rossrv", "show", "WordCount") == (
        "[basics/WordCount]:\nstring words\n---\nuint32 count\n\n"
    )


def test_timer_action_messages():
    assert show("rosmsg", "show", "basics/TimerGoal") == "duration time_to_wait\n\n"
    goal = show("rosmsg", "show", "basics/TimerActionGoal").splitlines()
    assert goal == [
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
    assert show("rosmsg", "show", "basics/TimerResult").split("\n")[:2] == [
        "duration time_elapsed",
        "uint32 updates_sent",
    ]
    assert show("rosmsg", "show", "basics/TimerFeedback").split("\n")[:2] == [
        "duration time_elapsed",
        "duration time_remaining",
    ]
    # As in the book: only msg/ files are listed; the Timer* messages are generated.
    assert show("rosmsg", "package", "basics") == "basics/Complex\n"
