"""The timer action's logic (chapter 5) on a fake clock: feedback count, preemption, checks."""

import argparse

import pytest
from basics import timer


class FakeClock:
    """A clock that advances only when slept; a cancel can be scheduled at a given time."""

    def __init__(self, cancel_at=None):
        self.t = 100.0
        self.start = self.t
        self.cancel_at = cancel_at
        self.feedback = []

    def now(self):
        return self.t

    def sleep(self, seconds):
        assert seconds > 0
        self.t += min(max(seconds, 1e-6), 0.01)  # a real sleep always lets time pass

    def preempt_requested(self):
        return self.cancel_at is not None and self.t - self.start >= self.cancel_at

    def publish(self, elapsed, remaining):
        self.feedback.append((round(elapsed, 6), round(remaining, 6)))

    def run(self, wait):
        return timer.run_timer(wait, self.now, self.sleep, self.preempt_requested, self.publish)


def test_five_second_goal_sends_five_updates_and_ends_on_time():
    clock = FakeClock()
    outcome, elapsed, updates = clock.run(5.0)
    assert (outcome, updates) == ("succeeded", 5)
    assert elapsed == pytest.approx(5.0, abs=0.011)
    assert [e for e, _ in clock.feedback] == pytest.approx([0, 1.1, 2.1, 3.1, 4.1], abs=0.011)
    assert all(e + r == pytest.approx(5.0) for e, r in clock.feedback)


def test_cancel_at_three_seconds_preempts_after_three_updates():
    clock = FakeClock(cancel_at=3.0)
    outcome, elapsed, updates = clock.run(5.0)
    assert (outcome, updates) == ("preempted", 3)
    assert elapsed == pytest.approx(3.0, abs=0.011)


def test_cancel_is_noticed_between_ticks():
    clock = FakeClock(cancel_at=1.5)
    outcome, elapsed, updates = clock.run(5.0)
    assert (outcome, updates) == ("preempted", 2)
    assert elapsed == pytest.approx(1.5, abs=0.011)


def test_zero_goal_succeeds_at_once():
    clock = FakeClock()
    assert clock.run(0.0) == ("succeeded", 0.0, 0)


def test_fractional_goal_does_not_oversleep():
    clock = FakeClock()
    outcome, elapsed, updates = clock.run(1.5)
    assert (outcome, updates) == ("succeeded", 2)
    assert elapsed == pytest.approx(1.5, abs=0.011)


@pytest.mark.parametrize(
    "seconds, problem",
    [
        (5.0, None),
        (0.0, None),
        (60.0, None),
        (60.5, timer.TOO_LONG),
        (500.0, "Timer aborted due to too-long wait"),
        (-1.0, "Timer aborted due to negative wait (-1.000000 s)"),
        (float("nan"), "Timer aborted due to invalid wait (nan)"),
    ],
)
def test_goal_problem(seconds, problem):
    assert timer.goal_problem(seconds) == problem


def test_seconds_arg():
    assert timer.seconds_arg("2.5") == 2.5
    assert timer.seconds_arg("-3") == -3.0
    for bad in ("abc", "", "nan", "inf", "1e12"):
        with pytest.raises(argparse.ArgumentTypeError):
            timer.seconds_arg(bad)


def test_delay_arg_refuses_negative():
    assert timer.delay_arg("3") == 3.0
    with pytest.raises(argparse.ArgumentTypeError, match="negative"):
        timer.delay_arg("-1")


def test_printouts_match_the_book():
    assert timer.feedback_lines(1.001626, 3.998374) == [
        "[Feedback] Time elapsed: 1.001626",
        "[Feedback] Time remaining: 3.998374",
    ]
    assert timer.result_lines(3, "Timer completed successfully", 5.008076, 5) == [
        "[Result] State: 3",
        "[Result] Status: Timer completed successfully",
        "[Result] Time elapsed: 5.008076",
        "[Result] Updates sent: 5",
    ]
    assert timer.result_lines(4, "x", None, None)[-1] == "[Result] (the server sent no result)"
