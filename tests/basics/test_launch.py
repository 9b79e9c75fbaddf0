"""Chapter 2: `roslaunch basics talker_listener.launch` starts both nodes; Ctrl+C stops them."""

import signal


def test_talker_listener_launch(ros):
    launch = ros.start(["roslaunch", "basics", "talker_listener.launch"])

    def nodes():
        return set(ros.run(["rosnode", "list"], check=False).stdout.split())

    ros.wait_for(lambda: {"/talker", "/listener"} <= nodes(), timeout=40, what="both nodes")
    ros.wait_for(
        lambda: "/listener I heard hello world" in ros.output(launch),
        timeout=30,
        what="the listener to hear the talker",
    )
    assert ros.stop(launch, sig=signal.SIGINT, timeout=30) == 0
    ros.wait_for(lambda: not ({"/talker", "/listener"} & nodes()), what="nodes to go")
