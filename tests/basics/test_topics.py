"""Chapter 3, topics: counter, subscriber, latched topic, Complex messages, doubler; chapter 2
naming: remapping, __ns, __name."""

import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import lockstep  # noqa: E402


def test_counter_publishes_consecutive_integers_at_2_hz(ros, master):
    """One message per 0.5 s of sim time, on a /clock that waits for each message (lockstep):
    the count n goes out at the first tick at or after its deadline n * 0.5 s from start."""
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    period, ticks = 0.5, 40
    clock = lockstep.start(ros, "counter", period, ticks)
    ros.start(["rosrun", "basics", "topic_publisher.py"])
    messages = lockstep.finish(ros, clock)
    values = [m["msg"]["data"] for m in messages]
    assert values == list(range(values[0], values[0] + len(values)))
    # rospy.Rate may send its first counts at once (started before the first /clock): from
    # count 3 on, each count's tick minus its deadline is the same offset (up to the slack).
    steady = [m for m in messages if m["msg"]["data"] >= 3]
    assert len(steady) >= ticks - 3
    offsets = [round((m["clock"] - 1000.0) / period) - m["msg"]["data"] for m in steady]
    assert max(offsets) - min(offsets) <= lockstep.SLACK_TICKS, offsets
    # The rate: counts per sim second over the steady run, exact within the slack.
    span = steady[-1]["clock"] - steady[0]["clock"]
    counts = steady[-1]["msg"]["data"] - steady[0]["msg"]["data"]
    assert abs(span - counts * period) <= lockstep.SLACK_TICKS * period, (span, counts)

    info = ros.run(["rostopic", "info", "counter"]).stdout
    assert "Type: std_msgs/Int32" in info
    assert "/topic_publisher" in info


def test_subscriber_prints_what_arrives_on_counter(ros, master):
    sub = ros.start(["rosrun", "basics", "topic_subscriber.py"])
    ros.wait_for(lambda: master.subscribers("counter"), timeout=60, what="the subscription")
    # The book's `rostopic pub counter std_msgs/Int32 1000000`: one latched message, kept
    # until the subscriber has printed it (`-1` would latch it for 3 s only, which a loaded
    # machine's connection can take longer than).
    once = ros.start(["rostopic", "pub", "counter", "std_msgs/Int32", "1000000"])

    def printed():
        return [int(x) for x in re.findall(r"^(-?\d+)$", ros.output(sub), re.M)]

    ros.wait_for(lambda: printed(), timeout=60, what="the subscriber to print 1000000")
    ros.stop(once)
    ros.start(["rosrun", "basics", "topic_publisher.py"])

    ros.wait_for(lambda: len(printed()) >= 4, timeout=60, what="four printed integers")
    values = printed()
    assert values[0] == 1000000
    counter = values[1:]
    assert counter == list(range(counter[0], counter[0] + len(counter)))


def test_late_subscriber_gets_the_last_latched_message(ros):
    pub = ros.start(["rosrun", "basics", "latched_publisher.py", "_count:=3"])
    ros.wait_for(lambda: "published 3 message(s)" in ros.output(pub), 60, "publishing")
    echoed = ros.run(["rostopic", "echo", "-n", "1", "latched"], timeout=60).stdout
    assert echoed.splitlines()[0] == 'data: "latched message 3 of 3"'


def test_complex_messages_flow_from_publisher_to_subscriber(ros, master):
    ros.start(["rosrun", "basics", "message_publisher.py"])
    sub = ros.start(["rosrun", "basics", "message_subscriber.py"])
    master.wait_for_topic("complex")
    assert ros.run(["rostopic", "type", "complex"]).stdout.strip() == "basics/Complex"
    messages = ros.echo("complex", count=3)
    for m in messages:
        assert set(m["msg"]) == {"real", "imaginary"}
        assert 0.0 <= m["msg"]["real"] < 1.0 and 0.0 <= m["msg"]["imaginary"] < 1.0

    def printed():
        return re.findall(r"^Real: (\S+)\nImaginary: (\S+)\n\n", ros.output(sub), re.M)

    ros.wait_for(lambda: len(printed()) >= 2, 60, "the subscriber's printout")
    assert all(0.0 <= float(r) < 1.0 and 0.0 <= float(i) < 1.0 for r, i in printed())


def test_doubler_publishes_twice_its_input(ros, master):
    doubler = ros.start(["rosrun", "basics", "doubler.py"])
    master.wait_for_topic("doubled")
    probe = ros.probe(["doubled"], count=2, timeout=60)
    # 2**30 doubled overflows Int32: the doubler warns and publishes nothing for it.
    # Latched until the end (not `-1`, which latches for 3 s only): each reaches the doubler
    # once, however long its connection takes.
    for args in (["21"], ["--", "-7"], ["1073741824"]):
        ros.start(["rostopic", "pub", "number", "std_msgs/Int32", *args])
    doubled = sorted(m["msg"]["data"] for m in probe.wait(70))
    assert doubled == [-14, 42]
    ros.wait_for(lambda: "does not fit in an Int32" in ros.output(doubler), 60, "overflow warning")
    assert doubler.poll() is None


def test_remapping_name_and_namespace(ros, master):
    """`__ns`, `__name` and `topic:=other` on the command line (chapter 2)."""
    cmd = ["rosrun", "basics", "topic_publisher.py", "__ns:=robot1", "__name:=counter1"]
    ros.start([*cmd, "counter:=numbers"])
    master.wait_for_topic("/robot1/numbers")
    assert master.publishers("/robot1/numbers") == {"/robot1/counter1"}
    assert not master.publishers("/counter") and not master.publishers("/robot1/counter")
    values = [m["msg"]["data"] for m in ros.echo("/robot1/numbers", count=2)]
    assert values[1] == values[0] + 1


def test_two_talkers_renamed_feed_one_listener(ros, master):
    ros.start(["rosrun", "basics", "talker.py", "__name:=talker1"])
    ros.start(["rosrun", "basics", "talker.py", "__name:=talker2"])
    listener = ros.start(["rosrun", "basics", "listener.py"])
    both = {"/talker1", "/talker2"}
    ros.wait_for(lambda: master.publishers("chatter") == both, 60, "both talkers")
    ros.wait_for(lambda: "I heard hello world" in ros.output(listener), 60, "listener output")
    assert master.subscribers("chatter") == {"/listener"}
