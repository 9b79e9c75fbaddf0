"""rqt_plot and rqt_graph stand-ins against a live graph: sampled values and drawn edges."""

import csv
import os
import shutil
import xmlrpc.client
from pathlib import Path

HERE = Path(__file__).resolve().parent
PYTHON = "/usr/bin/python3"
TWIST = "{linear: {x: 0.5}, angular: {z: -0.3}}"
CALLER = "/rqt_lite_tests"
# Runs argv[1:] with SIGINT's default action (KeyboardInterrupt in Python).
DEFAULT_SIGINT = (
    "import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); "
    "os.execvp(sys.argv[1], sys.argv[1:])"
)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    by_series = {}
    for row in rows:
        by_series.setdefault(row["series"], []).append((float(row["time"]), float(row["value"])))
    return by_series


def publish_cmd_vel(ros):
    ros.start(["rostopic", "pub", "-r", "10", "/cmd_vel", "geometry_msgs/Twist", TWIST])
    ros.wait_for_topic("cmd_vel")


def test_rqt_plot_lands_on_path_from_devel_bin():
    for tool in ("rqt_plot", "rqt_graph"):
        found = shutil.which(tool)
        assert found, f"{tool} not on PATH: source catkin_ws/devel/setup.bash"
        assert Path(found).parent.name == "bin" and os.access(found, os.X_OK)


def node_of(ros, topic, prefix, publishers=False):
    """The node (name, XML-RPC proxy) whose name starts with `prefix` that subscribes to (or
    publishes) `topic`."""
    master = xmlrpc.client.ServerProxy(ros.env["ROS_MASTER_URI"])
    _, _, state = master.getSystemState(CALLER)
    nodes = dict(state[0 if publishers else 1]).get(topic, [])
    name = next(n for n in nodes if n.startswith(prefix))
    _, _, uri = master.lookupNode(CALLER, name)
    return name, xmlrpc.client.ServerProxy(uri)


def counts(node, topic, publishers=False):
    """Messages per connection of `node` on `topic`, from its getBusStats."""
    _, _, (pub_stats, sub_stats, _) = node.getBusStats(CALLER)
    if publishers:
        conns = next((c for t, _, c in pub_stats if t == topic), [])
        return [c[2] for c in conns if c[3]]
    conns = next((c for t, c in sub_stats if t == topic), [])
    return [c[2] for c in conns if c[4]]


def test_rqt_plot_book_fields_to_png_with_samples(ros, tmp_path):
    # Sim time: tick_publisher.py sends one Twist per 0.1 s tick of its /clock, once
    # rqt_plot is connected; rqt_plot samples each on the ROS (sim) time axis.
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    png, samples = tmp_path / "plot.png", tmp_path / "samples.csv"
    fields = ["cmd_vel/linear/x", "cmd_vel/angular/z"]
    count = 30
    ros.start([PYTHON, str(HERE / "tick_publisher.py"), "--count", str(count)])
    ros.wait_for_topic("cmd_vel")
    # Ctrl-C ends the sampling: SIGINT at its default (a test run from a shell's background
    # job inherits it ignored, and rqt_plot, file mode, leaves Python's default in place).
    cmd = ["rqt_plot", *fields, "--output", png, "--duration", "600", "--csv", samples]
    plot = ros.start([PYTHON, "-c", DEFAULT_SIGINT, *map(str, cmd)], name="rqt_plot")

    def received():
        try:
            return counts(node_of(ros, "/cmd_vel", "/rqt_plot")[1], "/cmd_vel")
        except StopIteration:  # not subscribed yet
            return []

    ros.wait_for(lambda: received() == [count], 90, f"rqt_plot to receive {count} Twists")
    assert ros.stop(plot, timeout=180) == 0, ros.output(plot)  # Ctrl-C: write and exit
    assert "rqt_plot: wrote" in ros.output(plot)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    series = read_csv(samples)
    assert set(series) == {"/cmd_vel/linear/x", "/cmd_vel/angular/z"}
    assert {v for _, v in series["/cmd_vel/linear/x"]} == {0.5}
    assert {v for _, v in series["/cmd_vel/angular/z"]} == {-0.3}
    # Every message (the last may still be in rqt_plot's callback when Ctrl-C comes)...
    times = [t for t, _ in series["/cmd_vel/linear/x"]]
    assert count - 1 <= len(times) <= count
    # ... on the ROS time axis: sim seconds on the clock's 0.1 s ticks since the first sample
    assert times[0] == 0.0 and times == sorted(times) and times[-1] <= count * 0.1
    assert all(abs(t * 10 - round(t * 10)) < 1e-6 for t in times), times


def test_rqt_plot_array_index_and_svg_via_rosrun(ros, tmp_path):
    ros.start(
        [
            "rostopic",
            "pub",
            "-r",
            "10",
            "/arr",
            "std_msgs/Float64MultiArray",
            "{data: [1.5, 2.5, 3.5]}",
        ]
    )
    ros.wait_for_topic("arr")
    svg, samples = tmp_path / "plot.svg", tmp_path / "s.csv"
    ros.run(
        [
            "rosrun",
            "rqt_lite",
            "rqt_plot",
            "/arr/data[1]",
            "arr/data[-1]",
            "-o",
            str(svg),
            "-d",
            "2",
            "--csv",
            str(samples),
        ],
        timeout=90,
    )
    assert b"<svg" in svg.read_bytes()[:500]
    series = read_csv(samples)
    assert {v for _, v in series["/arr/data[1]"]} == {2.5}
    assert {v for _, v in series["/arr/data[-1]"]} == {3.5}


def test_rqt_plot_names_a_bad_field_and_exits_nonzero(ros, tmp_path):
    publish_cmd_vel(ros)
    done = ros.run(
        ["rqt_plot", "cmd_vel/linar/x", "-o", str(tmp_path / "p.png"), "-d", "1"],
        check=False,
        timeout=90,
    )
    assert done.returncode == 1
    assert "no field 'linar'" in done.stderr and "linear, angular" in done.stderr


def test_rqt_plot_rejects_an_unknown_output_format(ros, tmp_path):
    done = ros.run(["rqt_plot", "x/y", "-o", str(tmp_path / "p.jpg")], check=False)
    assert done.returncode == 2 and ".png or .svg" in done.stderr
    assert not (tmp_path / "p.jpg").exists()


def test_rqt_graph_talker_chatter_listener(ros, tmp_path):
    ros.start(
        ["rostopic", "pub", "-r", "5", "/chatter", "std_msgs/String", "hello", "__name:=talker"]
    )
    ros.start(["rostopic", "echo", "/chatter", "__name:=listener"])
    ros.start(
        ["rostopic", "pub", "-r", "5", "/nobody_listens", "std_msgs/String", "x", "__name:=lonely"]
    )
    ros.wait_for_topic("chatter")
    ros.wait_for_topic("nobody_listens")

    def has_listener():
        info = ros.run(["rostopic", "info", "/chatter"], check=False).stdout
        return "/listener" in info

    ros.wait_for(has_listener, 20, "listener to subscribe")
    dot_path = tmp_path / "graph.dot"
    ros.run(["rqt_graph", "--output", str(dot_path)])
    dot = dot_path.read_text()
    assert '"n/talker" [label="/talker", shape=ellipse];' in dot
    assert '"t/chatter" [label="/chatter", shape=box];' in dot
    assert '"n/talker" -> "t/chatter";' in dot
    assert '"t/chatter" -> "n/listener";' in dot
    assert "rosout" not in dot and "nobody_listens" not in dot  # rqt_graph's default hides

    everything = ros.run(["rqt_graph", "--all", "--output", "-"]).stdout
    assert '"n/lonely" -> "t/nobody_listens";' in everything
    assert '"n/rosout" -> "t/rosout_agg";' in everything

    for ext, magic in ((".png", b"\x89PNG"), (".svg", b"<svg")):
        out = tmp_path / ("graph" + ext)
        ros.run(["rqt_graph", "-o", str(out)])
        assert magic in out.read_bytes()[:400]
    assert "/chatter" in (tmp_path / "graph.svg").read_text()


def test_rqt_graph_without_a_master_is_a_clear_error(tmp_path):
    from roskit import free_port, ros_environment

    env = ros_environment(free_port())
    import subprocess

    done = subprocess.run(
        ["rqt_graph", "-o", str(tmp_path / "g.dot")],
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode != 0
    assert "cannot reach the ROS master" in done.stderr
    assert not (tmp_path / "g.dot").exists()
