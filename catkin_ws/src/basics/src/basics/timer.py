"""The Timer action of chapter 5 without ROS: goal checks, the server's loop, printouts."""

import argparse
import math

MAX_WAIT = 60.0  # seconds; the fancy server aborts longer goals
TOO_LONG = "Timer aborted due to too-long wait"
NEGATIVE = "Timer aborted due to negative wait"
SUCCEEDED = "Timer completed successfully"
PREEMPTED = "Timer preempted"
FEEDBACK_PERIOD = 1.0  # seconds between feedback messages
# Feedback after the first goes out this late, so that a cancel the client sends at exactly
# k seconds (the book cancels after 3 s) lands before feedback k despite network and
# scheduling jitter, as in the book's run (3 updates, not 4).
TICK_LAG = 0.1
# A ROS duration travels as int32 seconds; larger values cannot be serialised.
MAX_SENDABLE = 2**31 - 1


def goal_problem(seconds, max_wait=MAX_WAIT):
    """Why the fancy server refuses a goal of `seconds`, or None if it accepts it."""
    if not math.isfinite(seconds):
        return f"Timer aborted due to invalid wait ({seconds})"
    if seconds < 0:
        return f"{NEGATIVE} ({seconds:f} s)"
    if seconds > max_wait:
        return TOO_LONG
    return None


def run_timer(
    wait, now, sleep, preempt_requested, publish_feedback, period=FEEDBACK_PERIOD, lag=TICK_LAG
):
    """The fancy server's loop: feedback every `period` until `wait` seconds have passed.

    `now()` gives seconds, `sleep(s)` waits up to s seconds (short naps keep preemption
    prompt), `preempt_requested()` polls the client's cancel request, and
    `publish_feedback(elapsed, remaining)` sends one update. Feedback k goes out at
    k * period (+ lag for k >= 1). Returns (outcome, elapsed, updates) with outcome
    "succeeded" or "preempted".
    """
    start = now()
    updates = 0
    while now() - start < wait:
        if preempt_requested():
            return "preempted", now() - start, updates
        elapsed = now() - start
        publish_feedback(elapsed, wait - elapsed)
        updates += 1
        # Sleep to the next tick on a fixed schedule (no drift), never past the goal's end.
        next_tick = min(updates * period + lag, wait)
        while not preempt_requested() and now() - start < next_tick:
            sleep(next_tick - (now() - start))
    return "succeeded", now() - start, updates


def seconds_arg(text):
    """argparse type: a finite number of seconds that fits in a ROS duration."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number of seconds: {text!r}") from None
    if not math.isfinite(value) or abs(value) > MAX_SENDABLE:
        raise argparse.ArgumentTypeError(f"seconds must be finite and within ±{MAX_SENDABLE}")
    return value


def delay_arg(text):
    """argparse type: a non-negative number of seconds."""
    value = seconds_arg(text)
    if value < 0:
        raise argparse.ArgumentTypeError(f"a delay cannot be negative: {text!r}")
    return value


def feedback_lines(elapsed, remaining):
    return [
        f"[Feedback] Time elapsed: {elapsed:f}",
        f"[Feedback] Time remaining: {remaining:f}",
    ]


def result_lines(state, status, elapsed, updates):
    """The fancy client's summary; elapsed/updates are None when the server sent no result."""
    lines = [f"[Result] State: {state:d}", f"[Result] Status: {status}"]
    if elapsed is None:
        lines.append("[Result] (the server sent no result)")
    else:
        lines.append(f"[Result] Time elapsed: {elapsed:f}")
        lines.append(f"[Result] Updates sent: {updates:d}")
    return lines
