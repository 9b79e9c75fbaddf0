"""The live windows of rqt_plot and rqt_graph on a virtual display (Xvfb)."""

import shutil
import subprocess

import pytest

pytestmark = pytest.mark.skipif(
    not (shutil.which("xvfb-run") and shutil.which("import")),
    reason="needs xvfb-run (xvfb, xauth) and ImageMagick's import",
)

SCRIPT = """
{tool} &
pid=$!
sleep {wait}
import -window root {shot}
kill -INT $pid
wait $pid
echo "exit=$?"
"""


def on_virtual_display(ros, tool, shot, wait=10):
    cmd = [
        "xvfb-run",
        "-a",
        "-s",
        "-screen 0 1024x768x24",
        "bash",
        "-c",
        SCRIPT.format(tool=tool, wait=wait, shot=shot),
    ]
    return ros.run(cmd, timeout=120)


def unique_colours(png):
    done = subprocess.run(
        ["identify", "-format", "%k", str(png)], capture_output=True, text=True, check=True
    )
    return int(done.stdout.strip())


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
    shot, samples = tmp_path / "screen.png", tmp_path / "s.csv"
    done = on_virtual_display(
        ros, f"rqt_plot cmd_vel/linear/x cmd_vel/angular/z --csv {samples}", shot
    )
    assert "exit=0" in done.stdout, done.stdout + done.stderr
    rows = samples.read_text().splitlines()[1:]
    assert len(rows) >= 20
    assert {r.split(",")[2] for r in rows} == {"0.25", "0.5"}
    assert unique_colours(shot) > 20  # a drawn figure, not an empty root window


def test_rqt_graph_window_shows_the_graph(ros, tmp_path):
    ros.start(["rostopic", "pub", "-r", "5", "/chatter", "std_msgs/String", "hi", "__name:=talker"])
    ros.start(["rostopic", "echo", "/chatter", "__name:=listener"])
    ros.wait_for_topic("chatter")
    shot = tmp_path / "screen.png"
    done = on_virtual_display(ros, "rqt_graph --refresh 1", shot, wait=6)
    assert "exit=" in done.stdout, done.stdout + done.stderr
    assert unique_colours(shot) > 10
