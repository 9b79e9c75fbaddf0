#!/usr/bin/python3
"""A /clock that advances in lock step with the node under test, so that rates and durations
measured in sim time cannot be upset by a loaded machine.

The clock holds --start until the node is connected (its --gate publisher, its /clock
subscription, the --say topics' subscribers), then moves in ticks of --period sim seconds.
After each tick it waits (wall time, up to --timeout) for a new message on --gate before the
next tick: a node that publishes once a period is never left behind, however slow the machine.

What that guarantees, and why tests allow two ticks of slack (SLACK_TICKS in lockstep.py):
rospy.Rate publishes each message once the clock reaches its deadline, never earlier; with
the clock held there, a message arrives at the tick of its deadline, or later by as many
messages as were still on their way when the clock moved on. Only a start-up can leave such
messages: rospy.Rate sends one or two at once when it was created before the first /clock.
After that, one message per tick keeps the offset constant.

rospy.sleep reads the clock twice; a tick landing in between moves its deadline one tick
later. That is unlikely here (rospy sends a message from its queue thread, normally once the
node's main thread sleeps); should it happen, the clock moves on without a message once
(never twice in a row) after --credit wall seconds, and the node catches up.

Injections at sim time T (seconds after --start, a whole number of ticks), made after that
tick's message and before the next tick, which waits until the node has read them (its own
count of messages received, tests/tools/delivery.py):
  --say TOPIC=TEXT@T[/ECHOES]  publish std_msgs/String TEXT on TOPIC, then wait for ECHOES
                               more changes of the gate message (a node that answers each
                               input at once with a new value). Changes, not messages: a
                               rate message still on its way would pass for the answer, and
                               the node could then take the input ticks late.
  --type TEXT@T[-T2]           write TEXT to the terminal --tty-fd at T (and every tick to T2)

With --step-service (the simulator's ~step, std_srvs/Trigger, when it starts paused) the
simulator is the clock instead: each tick calls it --steps-per-tick times.

Output: one JSON line per gate message, {"tick", "clock", "msg"} (clock in sim seconds: the
time the clock showed when the message arrived), and {"credit": tick} for each credit.
Library use (scripts that inject other messages): Lockstep(...).run(ticks, on_tick).
"""

import argparse
import json
import os
import sys
import threading
import time
import warnings
from pathlib import Path

import rosgraph
import rospy
import rostopic
from rosgraph_msgs.msg import Clock
from std_msgs.msg import String
from std_srvs.srv import Trigger

sys.path.insert(0, str(Path(__file__).resolve().parent))
from delivery import Delivery, a_publisher_sends_to_us  # noqa: E402
from topic_probe import to_plain  # noqa: E402

NS = 1_000_000_000
REPUBLISH = 0.02  # wall seconds between repeats of the current clock (late subscribers)


class LockstepError(RuntimeError):
    pass


class Lockstep:
    """Publishes /clock itself and advances it one tick at a time."""

    def __init__(self, gate, period, start=1000.0, timeout=60.0, credit=5.0, out=None):
        self.period_ns = round(period * NS)
        self.clock_ns = self.start_ns = round(start * NS)
        self.timeout = timeout
        self.credit = credit
        self.out = open(out, "w") if out else None
        self.cond = threading.Condition()
        self.arrivals = 0
        self.changes = 0  # gate messages unlike the one before them
        self.last_msg = None
        self.tick = 0
        self.gate_topic = rospy.resolve_name(gate)
        self.gate_sub = None
        self.inputs = []  # publishers whose subscribers must be connected before tick 1
        self.deliveries = []  # their Delivery counts, once connected
        self._last_was_credit = False
        self.clock_pub = rospy.Publisher("/clock", Clock, queue_size=10)

    # -- the clock (overridden for the simulator) -----------------------------------------
    def publish_clock(self):
        secs, nsecs = divmod(self.clock_ns, NS)
        self.clock_pub.publish(Clock(clock=rospy.Time(secs, nsecs)))

    def advance(self):
        self.publish_clock()

    def clock_subscribers_connected(self):
        me = rospy.get_name()
        state = rosgraph.Master(me).getSystemState()
        others = [s for s in dict(state[1]).get("/clock", []) if s != me]
        return self.clock_pub.get_num_connections() >= len(others) > 0

    # -- set-up ---------------------------------------------------------------------------
    def wait(self, ready, what):
        """Repeat the clock until ready() (the wall-time limit catches a broken node)."""
        deadline = time.monotonic() + self.timeout
        while not ready():
            if time.monotonic() > deadline:
                raise LockstepError(f"{what}: nothing within {self.timeout} s")
            self.publish_clock()
            with self.cond:
                self.cond.wait(REPUBLISH)

    def connect(self):
        def subscribed():
            msg_class, real, _ = rostopic.get_topic_class(self.gate_topic, blocking=False)
            if msg_class is not None:
                self.gate_sub = rospy.Subscriber(real, msg_class, self._on_gate, queue_size=1000)
            return msg_class is not None

        self.wait(subscribed, f"a publisher of {self.gate_topic}")
        self.wait(lambda: a_publisher_sends_to_us(self.gate_sub), "the gate connection")
        self.wait(self.clock_subscribers_connected, "the /clock subscribers")
        for pub in self.inputs:
            self.wait(lambda p=pub: p.get_num_connections() > 0, f"a subscriber of {pub.name}")
        self.deliveries = [Delivery(pub) for pub in self.inputs]

    def inputs_taken(self):
        """Wait until the node has read what on_tick published: written to its socket is
        not enough, its receive thread may lag ticks behind under load."""
        for delivery in self.deliveries:
            self.wait(delivery.taken, f"{delivery.topic} read by its subscribers")

    def _on_gate(self, msg):
        plain = to_plain(msg)
        with self.cond:
            self._write({"tick": self.tick, "clock": self.clock_ns / NS, "msg": plain})
            self.arrivals += 1
            if self.arrivals > 1 and plain != self.last_msg:
                self.changes += 1
            self.last_msg = plain
            self.cond.notify_all()

    def _write(self, record):
        if self.out:
            self.out.write(json.dumps(record) + "\n")
            self.out.flush()

    # -- running --------------------------------------------------------------------------
    def arrived(self):
        with self.cond:
            return self.arrivals

    def changed(self):
        with self.cond:
            return self.changes

    def expect(self, target, credit=False, count="arrivals"):
        """Wait until `target` gate messages have arrived in all (count="changes": changes
        of the message); with `credit`, move on without them once --credit wall seconds
        have passed (not twice in a row)."""
        now = time.monotonic()
        deadline, credit_at = now + self.timeout, now + self.credit
        while True:
            with self.cond:
                if getattr(self, count) >= target:
                    return True
            now = time.monotonic()
            if credit and self.credit and now > credit_at and not self._last_was_credit:
                with self.cond:
                    self._write({"credit": self.tick})
                return False
            if now > deadline:
                raise LockstepError(
                    f"no {'new value' if count == 'changes' else 'message'} on "
                    f"{self.gate_topic} within {self.timeout} s at sim time "
                    f"{self.clock_ns / NS:.3f} (tick {self.tick})"
                )
            self.publish_clock()
            with self.cond:
                self.cond.wait(REPUBLISH)

    def run(self, ticks, on_tick=None):
        """Advance `ticks` ticks; on_tick(tick) injects inputs after the tick's message and
        returns how many changes of the gate message they cause (on_tick(0): before the
        first tick, answers not awaited)."""
        if on_tick is not None:
            on_tick(0)
            self.inputs_taken()
        for _ in range(ticks):
            target = self.arrived() + 1  # counted before the tick: the node may be quick
            with self.cond:
                self.tick += 1
                self.clock_ns += self.period_ns
            self.advance()
            self._last_was_credit = not self.expect(target, credit=True)
            if on_tick is not None:
                target = self.changed()
                echoes = on_tick(self.tick)
                self.inputs_taken()
                if echoes:
                    self.expect(target + echoes, count="changes")
        if self.out:
            self.out.close()


def run_program(clock, ticks, on_tick, prog):
    """A lock-step helper program's run: connect, advance `ticks` ticks; its exit status,
    0, or 4 with the error on stderr."""
    try:
        clock.connect()
        clock.run(ticks, on_tick)
    except LockstepError as error:
        print(f"{prog}: {error}", file=sys.stderr)
        return 4
    return 0


def input_publisher(topic, msg_class):
    """A publisher for what on_tick injects. Synchronous (queue_size=None): publish() has
    written the message to every subscriber's socket before the next tick's /clock goes
    out, whereas a queued publisher's writer thread can fall ticks behind the clock's under
    load, and the node would then take its inputs late."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # rospy warns about queue_size=None; it is meant
        return rospy.Publisher(topic, msg_class, queue_size=None)


class SimulatorLockstep(Lockstep):
    """The paused simulator is the clock: each tick calls its ~step service."""

    def __init__(self, gate, period, step_service, steps_per_tick, **kwargs):
        super().__init__(gate, period, **kwargs)
        rospy.wait_for_service(step_service, timeout=self.timeout)
        self.step = rospy.ServiceProxy(step_service, Trigger, persistent=True)
        self.steps_per_tick = steps_per_tick

    def publish_clock(self):
        pass  # the paused simulator repeats its own /clock

    def advance(self):
        for _ in range(self.steps_per_tick):
            answer = self.step()
            if not answer.success:
                raise LockstepError(f"{self.step.resolved_name}: {answer.message}")
        # "time 12.340000": the simulator's time after the step (to the microsecond)
        sim_ns = round(float(answer.message.split()[-1]) * 1e6) * 1000
        with self.cond:
            self.clock_ns = sim_ns

    def clock_subscribers_connected(self):
        return True  # the simulator's /clock, which the node finds by itself

    def connect(self):
        clock = rospy.wait_for_message("/clock", Clock, timeout=self.timeout)
        self.clock_ns = self.start_ns = clock.clock.to_nsec()
        super().connect()


def parse_at(text):
    """'X@T' or 'X@T-T2' -> (X, T, T2)."""
    what, _, when = text.rpartition("@")
    first, _, last = when.partition("-")
    return what, float(first), float(last or first)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("--gate", required=True, help="topic the node publishes every tick")
    parser.add_argument("--period", type=float, required=True, help="sim seconds per tick")
    parser.add_argument("--ticks", type=int, required=True)
    parser.add_argument("--start", type=float, default=1000.0)
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("--credit", type=float, default=5.0)
    parser.add_argument("--say", action="append", default=[], help="TOPIC=TEXT@T[/ECHOES]")
    parser.add_argument("--type", action="append", default=[], help="TEXT@T[-T2]")
    parser.add_argument("--tty-fd", type=int, help="terminal (pty master) for --type")
    parser.add_argument("--step-service", help="step this (paused) simulator instead")
    parser.add_argument("--steps-per-tick", type=int, default=1)
    args = parser.parse_args(rospy.myargv()[1:])

    rospy.init_node("lockstep_clock", disable_signals=True)
    common = dict(timeout=args.timeout, credit=args.credit, out=args.out)
    if args.step_service:
        clock = SimulatorLockstep(
            args.gate, args.period, args.step_service, args.steps_per_tick, **common
        )
    else:
        clock = Lockstep(args.gate, args.period, start=args.start, **common)

    def tick_of(seconds):
        return round(seconds / args.period)

    says = {}  # tick -> [(publisher, text, echoes)]
    publishers = {}
    for spec in args.say:
        topic, _, rest = spec.partition("=")
        rest, _, echoes = rest.partition("/")
        text, at, _ = parse_at(rest)
        if topic not in publishers:
            publishers[topic] = input_publisher(topic, String)
        says.setdefault(tick_of(at), []).append((publishers[topic], text, int(echoes or 0)))
    clock.inputs = list(publishers.values())
    typing = {}  # tick -> text
    for spec in args.type:
        text, first, last = parse_at(spec)
        for tick in range(tick_of(first), tick_of(last) + 1):
            typing[tick] = typing.get(tick, "") + text

    def on_tick(tick):
        echoes = 0
        for pub, text, expected in says.get(tick, []):
            pub.publish(text)
            echoes += expected
        if tick in typing:
            os.write(args.tty_fd, typing[tick].encode())
        return echoes

    return run_program(clock, args.ticks, on_tick, "lockstep_clock")


if __name__ == "__main__":
    sys.exit(main())
