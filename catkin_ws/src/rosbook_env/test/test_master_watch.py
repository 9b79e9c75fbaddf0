"""same_master: which (pid, /run_id) answers are the master a node registered with."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from rosbook_env.master_watch import same_master  # noqa: E402


def test_the_same_answer_is_the_same_master():
    assert same_master((41, "run-a"), (41, "run-a"))
    assert same_master((41, ""), (41, ""))  # rosmaster started alone never gets a /run_id


def test_a_run_id_set_after_the_master_first_answered_is_the_same_master():
    # roscore's roslaunch sets /run_id up to a poll (0.1 s) after rosmaster answers.
    assert same_master((57, ""), (57, "run-b"))


def test_a_new_pid_or_a_new_run_id_is_a_new_master():
    assert not same_master((41, "run-a"), (57, ""))
    assert not same_master((41, "run-a"), (57, "run-b"))
    assert not same_master((41, ""), (57, ""))
    assert not same_master((41, "run-a"), (41, "run-b"))  # the same pid again (a container)
    assert not same_master((41, "run-a"), (41, ""))  # ... before its roslaunch set /run_id


def test_no_master_known_at_start_makes_any_master_new():
    assert not same_master(None, (41, "run-a"))
