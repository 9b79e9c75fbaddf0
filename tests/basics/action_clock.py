#!/usr/bin/python3
"""Test helper (not a test): a /clock for the `timer` action that stands still until the
action has done what is due, so goal times measured in sim time do not depend on load.

The clock holds --start (with --free-until FILE: it moves 0.1 s every 20 ms until FILE
exists, so that a client waiting for the server can time out) until the server has started
a goal of --goal seconds (feedback 0; with --simple, a server without feedback: status
ACTIVE, or a result), then jumps from event to event, waiting at each for what is due:
  - feedback k at k * FEEDBACK_PERIOD + TICK_LAG (k >= 1, before the goal's end);
  - the result at the goal's end;
  - with --cancel-at T: the client's cancel at T, then the result a nap later.
With --client-out FILE (the client's stdout), each feedback is also waited for there, printed
by the client, before the clock moves on: actionlib's client drops feedback it handles after
the result (its state is DONE by then), and a clock that outran a stalled client would let
the result come while all feedback was still queued, so that it printed none.
rospy.sleep can overshoot a held time by one nap of the server (--poll, its preemption check
period): when nothing comes within --credit wall seconds, the clock moves on by one nap (once
for each event). So each event happens at its time, or at most that much later.
A --simple server may read its start time only after the jump to the goal's end (its ACTIVE
status goes out just before): without a result there, the clock jumps one goal length on.

Writes JSON lines {"topic", "clock", ...} to --out for feedback and result (with their
"elapsed", "remaining", "updates", "status"), cancel and goal; creates --out + ".ready" once
it hears the server's feedback, status and result.
"""

import argparse
import json
import math
import os
import sys
import threading
import time
from pathlib import Path

import rospy
from actionlib_msgs.msg import GoalID, GoalStatus, GoalStatusArray
from basics.msg import TimerActionFeedback, TimerActionGoal, TimerActionResult
from basics.timer import FEEDBACK_PERIOD, TICK_LAG
from rosgraph_msgs.msg import Clock

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from delivery import a_publisher_sends_to_us  # noqa: E402

NS = 1_000_000_000
REPEAT = 0.02  # wall seconds between repeats of the held clock
SIMPLE_PATIENCE = 5.0  # wall seconds for a --simple server's result before the second jump
FEEDBACK_LINE = "[Feedback] Time elapsed:"  # fancy_action_client's first line of a feedback


class ActionClock:
    def __init__(self, args):
        self.args = args
        self.clock_ns = round(args.start * NS)
        self.cond = threading.Condition()
        self.seen = {"feedback": [], "cancel": [], "result": [], "active": [], "goal": []}
        self.out = open(args.out, "w")
        self.pub = rospy.Publisher("/clock", Clock, queue_size=10)
        self.subscribers = {
            kind: rospy.Subscriber(topic, msg_class, self.record, (topic, kind), queue_size=100)
            for topic, kind, msg_class in (
                ("/timer/feedback", "feedback", TimerActionFeedback),
                ("/timer/cancel", "cancel", GoalID),
                ("/timer/result", "result", TimerActionResult),
                ("/timer/goal", "goal", TimerActionGoal),
            )
        }
        self.subscribers["status"] = rospy.Subscriber(
            "/timer/status", GoalStatusArray, self.on_status, queue_size=100
        )
        self.confirmed = set()  # kinds whose publisher has confirmed its end of the connection
        self.ready_file = args.out + ".ready"
        self.ready = False

    def record(self, msg, topic_kind):
        topic, kind = topic_kind
        with self.cond:
            self.seen[kind].append(msg)
            line = {"topic": topic, "clock": self.clock_ns / NS}
            if kind == "feedback":
                line["elapsed"] = msg.feedback.time_elapsed.to_sec()
                line["remaining"] = msg.feedback.time_remaining.to_sec()
            if kind == "result":
                line["elapsed"] = msg.result.time_elapsed.to_sec()
                line["updates"] = msg.result.updates_sent
                line["status"] = msg.status.text
            self.out.write(json.dumps(line) + "\n")
            self.out.flush()
            self.cond.notify_all()

    def on_status(self, msg):
        if any(s.status == GoalStatus.ACTIVE for s in msg.status_list):
            with self.cond:
                self.seen["active"].append(msg)
                self.cond.notify_all()

    def publish(self):
        secs, nsecs = divmod(self.clock_ns, NS)
        self.pub.publish(Clock(clock=rospy.Time(secs, nsecs)))
        self.mark_ready()

    def mark_ready(self):
        """Create --out + ".ready" once this clock hears everything a server sends (feedback,
        status, result): a test waits for it before it sends a goal, so that no one-off
        message (an abort's only result) goes out before the connection that carries it."""
        if not self.ready and self.hears("feedback", "status", "result"):
            with open(self.ready_file, "w"):
                pass
            self.ready = True

    def hears(self, *kinds):
        """A publisher of each of these topics sends to this clock. This clock's own count of
        connections is no proof: a message sent before the publisher adds its end (a server's
        only result) would be lost to it."""
        return all(self.publisher_sends(kind) for kind in kinds)

    def publisher_sends(self, kind):
        """A publisher of `kind`'s topic lists this clock among its connections (once true,
        it stays so: the server is not restarted)."""
        if kind not in self.confirmed and a_publisher_sends_to_us(self.subscribers[kind]):
            self.confirmed.add(kind)
        return kind in self.confirmed

    def result_seen(self):
        return self.count("result") > 0

    def count(self, kind):
        with self.cond:
            return len(self.seen[kind])

    def handled(self, kind, total):
        """`total` messages of `kind` seen; feedback also printed by the client (--client-out)."""
        if self.count(kind) < total:
            return False
        return kind != "feedback" or self.client_printed() >= total

    def client_printed(self):
        """Feedback blocks the client has printed (each starts with its elapsed line)."""
        if not self.args.client_out:
            return math.inf
        try:
            with open(self.args.client_out) as out:
                return out.read().count(FEEDBACK_LINE)
        except FileNotFoundError:
            return 0

    def hold_until(self, ready, what, credits=0, patience=None):
        """Repeat the clock until ready(); after --credit wall seconds without it, move on by
        one --poll (up to `credits` times). With `patience` (wall seconds), return False
        when it runs out instead of failing."""
        deadline = time.monotonic() + (patience or self.args.timeout)
        credit_at = time.monotonic() + self.args.credit
        while not ready():
            now = time.monotonic()
            if credits and now > credit_at:
                credits -= 1
                credit_at = now + self.args.credit
                self.clock_ns += round(self.args.poll * NS)
            if now > deadline:
                if patience:
                    return False
                raise TimeoutError(f"{what}: nothing within {self.args.timeout} s")
            self.publish()
            with self.cond:
                self.cond.wait(REPEAT)
        return True

    def run(self):
        args = self.args
        if args.free_until:
            while not os.path.exists(args.free_until):
                self.clock_ns += round(0.1 * NS)
                self.publish()
                time.sleep(REPEAT)
        start_ns = self.clock_ns
        started = "active" if args.simple else "feedback"

        # Before the goal can end, this clock must hear the server's result: its connection
        # to /timer/result is made apart from the status and feedback ones and can come
        # later on a loaded machine; a result sent before it would be missed.
        # A --simple server's ACTIVE status is sent once, on its own connection, and the held
        # clock stops actionlib's periodic status: the client's goal (its publisher was up long
        # before) also counts as the start; the schedule below allows for a server that reads
        # its start time after the jump.
        def goal_started():
            return self.handled(started, 1) or (args.simple and self.count("goal") > 0)

        self.hold_until(
            lambda: self.result_seen() or (goal_started() and self.hears("result")),
            "the server to start a goal",
        )
        wait = args.goal
        events = []  # (seconds after the goal, what is due, how many by then)
        k = 1
        while k * FEEDBACK_PERIOD + TICK_LAG < wait and not args.simple:
            events.append((k * FEEDBACK_PERIOD + TICK_LAG, "feedback", k + 1))
            k += 1
        events.append((wait, "result", 1))
        if args.simple:
            events.append((2 * wait, "result", 1))
        if args.cancel_at is not None:
            events = [e for e in events if e[0] < args.cancel_at]
            # The server naps through the cancel: it sees it after one more nap.
            events += [(args.cancel_at, "cancel", 1), (args.cancel_at + args.poll, "result", 1)]
        for at, kind, total in events:
            if self.count("result"):
                break  # aborted, or finished before its schedule says
            # A microsecond past the event: float seconds could round just below it.
            self.clock_ns = max(self.clock_ns, start_ns + round(at * NS) + 1000)
            credits = 0 if kind == "cancel" else 1
            if args.simple and at == wait:
                # The first end: the server may have read its start after the jump here.
                self.hold_until(self.result_seen, "the result", patience=SIMPLE_PATIENCE)
                continue
            # (The server's result also shows that a cancel came, should this clock have
            # missed the client's message.)
            self.hold_until(
                lambda k=kind, n=total: self.handled(k, n) or self.result_seen(), kind, credits
            )
        self.out.close()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--start", type=float, default=1000.0)
    parser.add_argument("--goal", type=float, required=True, help="the goal's seconds")
    parser.add_argument("--poll", type=float, required=True, help="the server's nap (s)")
    parser.add_argument("--cancel-at", type=float, help="sim s after the goal: the client cancels")
    parser.add_argument("--free-until", help="run the clock freely until this file exists")
    parser.add_argument("--simple", action="store_true", help="a server without feedback")
    parser.add_argument("--client-out", help="the client's stdout: wait for its printed feedback")
    parser.add_argument("--credit", type=float, default=1.0)
    parser.add_argument("--timeout", type=float, default=60.0)
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("action_clock", disable_signals=True)
    try:
        ActionClock(args).run()
    except TimeoutError as error:
        print(f"action_clock: {error}", file=sys.stderr)
        return 4
    return 0


if __name__ == "__main__":
    sys.exit(main())
