"""The live windows of rqt_plot and rqt_graph on a virtual display (Xvfb)."""

import os
import shutil
import signal
import sys
import xmlrpc.client
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from rviz_screenshot import RvizSession, count_rgb  # noqa: E402

pytestmark = pytest.mark.skipif(
    not (shutil.which("xvfb-run") and shutil.which("import") and shutil.which("xwininfo")),
    reason="needs xvfb-run (xvfb, xauth), ImageMagick's import and xwininfo",
)

CALLER = "/rqt_window_tests"
# matplotlib's first two line colours (C0, C1): the two plotted fields
BLUE, ORANGE = (31, 119, 180), (255, 127, 14)
# Pixels of a line across the axes (~600 px wide), far more than its legend entry (~30 px).
LINE_PIXELS = 300


def unique_colours(img):
    return len(np.unique(img.reshape(-1, 3), axis=0))


def on_virtual_display(ros, tmp_path, command):
    """`command` in its own Xvfb (RvizSession runs any command), screenshots on demand."""
    return RvizSession(command=command, env=ros.env, workdir=tmp_path, screen=(1024, 768))


def quit_with_ctrl_c(session, timeout=180):
    """SIGINT to the tool; returns its exit status (xvfb-run passes it on)."""
    os.kill(session.rviz_pid, signal.SIGINT)
    return session.proc.wait(timeout=timeout)


def samples_received(ros, prefix, topic):
    """Messages of `topic` the node named prefix* has received so far (its getBusStats)."""
    master = xmlrpc.client.ServerProxy(ros.env["ROS_MASTER_URI"])
    _, _, state = master.getSystemState(CALLER)
    names = [n for n in dict(state[1]).get(topic, []) if n.startswith(prefix)]
    if not names:
        return 0
    _, _, uri = master.lookupNode(CALLER, names[0])
    _, _, (_, subscriptions, _) = xmlrpc.client.ServerProxy(uri).getBusStats(CALLER)
    return sum(c[2] for t, conns in subscriptions if t == topic for c in conns)


def test_rqt_plot_window_plots_live_and_quits_on_ctrl_c(ros, tmp_path):
    ros.start(
        [
            "rostopic",
            "pub",
            "-r",
            "10",
            "/cmd_vel",
            "geometry_msgs/Twist",
            "{linear: {x: 0.25}, angular: {z: 0.5}}",
        ]
    )
    ros.wait_for_topic("cmd_vel")
    samples = tmp_path / "s.csv"
    command = ["rqt_plot", "cmd_vel/linear/x", "cmd_vel/angular/z", "--csv", str(samples)]
    with on_virtual_display(ros, tmp_path, command) as session:

        def both_lines_drawn(img):
            return min(count_rgb(img, BLUE, 40), count_rgb(img, ORANGE, 40)) > LINE_PIXELS

        shot, img = session.settle(both_lines_drawn, timeout=90, min_wait=0.5)
        assert both_lines_drawn(img), f"no live lines in {shot}"
        assert unique_colours(img) > 20  # a drawn figure, not an empty root window
        # 20 samples in the plot before quitting: count what rqt_plot has received
        ros.wait_for(lambda: samples_received(ros, "/rqt_plot", "/cmd_vel") >= 21, 60, "samples")
        assert quit_with_ctrl_c(session) == 0, session.log()
    rows = samples.read_text().splitlines()[1:]
    # (the last sample received may still be in rqt_plot's callback when Ctrl-C comes)
    assert sum(1 for r in rows if r.startswith("/cmd_vel/linear/x,")) >= 20
    assert {r.split(",")[2] for r in rows} == {"0.25", "0.5"}


def test_rqt_graph_window_shows_the_graph(ros, tmp_path):
    ros.start(["rostopic", "pub", "-r", "5", "/chatter", "std_msgs/String", "hi", "__name:=talker"])
    ros.start(["rostopic", "echo", "/chatter", "__name:=listener"])
    ros.wait_for_topic("chatter")
    with on_virtual_display(ros, tmp_path, ["rqt_graph", "--refresh", "1"]) as session:
        shot, img = session.settle(lambda im: unique_colours(im) > 10, timeout=90, min_wait=0.5)
        assert unique_colours(img) > 10, f"no graph drawn in {shot}"
        assert quit_with_ctrl_c(session) == 0, session.log()
