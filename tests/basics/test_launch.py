"""Chapter 2: `roslaunch basics talker_listener.launch` starts both nodes; Ctrl+C stops them."""

import signal


def test_talker_listener_launch(ros, master):
    launch = ros.start(["roslaunch", "basics", "talker_listener.launch"])
    pair = {"/talker", "/listener"}
    ros.wait_for(lambda: pair <= master.nodes(), timeout=60, what="both nodes")
    ros.wait_for(
        lambda: "/listener I heard hello world" in ros.output(launch),
        timeout=60,
        what="the listener to hear the talker",
    )
    assert ros.stop(launch, sig=signal.SIGINT, timeout=30) == 0
    ros.wait_for(lambda: not (pair & master.nodes()), timeout=30, what="the nodes to go")
