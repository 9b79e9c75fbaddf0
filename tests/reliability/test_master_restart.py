"""The graph survives the master: roscore killed (SIGKILL) and started again on the same port.

The project's nodes (rosbook_env.master_watch in Python, rosbook_env::MasterWatch in C++)
register their publishers, subscribers, services and private parameters again with the new
master. Both orders are checked, deterministically: the old nodes are stopped (SIGSTOP)
while the master restarts and new nodes join it, so each old publisher registers after a new
subscriber (the master then sends it a publisherUpdate) and each old subscriber after a new
publisher (it then learns of it from registerSubscriber).
"""

import os
import shutil
import signal
import subprocess
import xmlrpc.client
from contextlib import contextmanager

from roskit import CALLER_ID

TIMEOUT = 60  # wall seconds for a condition to come true on a loaded machine: only a hang limit


def restart_master(ros):
    """Kill roscore, its rosmaster and its rosout (roslaunch starts them in sessions of their
    own) with SIGKILL, and start a new roscore on the same port."""
    master = ros.master()
    pids = [master.getPid(CALLER_ID)[2]]
    code, _, rosout_uri = master.lookupNode(CALLER_ID, "/rosout")
    if code == 1:
        pids.append(xmlrpc.client.ServerProxy(rosout_uri).getPid(CALLER_ID)[2])
    for pid in pids:
        os.kill(pid, signal.SIGKILL)
    ros.stop(ros.core, sig=signal.SIGKILL)
    ros.wait_for(lambda: not any(alive(pid) for pid in pids), TIMEOUT, "the old master to die")
    ros.core = ros.start(["roscore", "-p", str(ros.port)], name="roscore-again")
    ros.wait_for_master()


def assert_registered_again_once(ros, proc):
    assert proc.poll() is None, ros.output(proc)
    assert ros.output(proc).count("master_watch: new master at") == 1, ros.output(proc)


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    with open(f"/proc/{pid}/stat") as stat:  # a zombie is dead too
        return stat.read().rsplit(")", 1)[1].split()[0] != "Z"


@contextmanager
def stopped(*procs):
    """SIGSTOP the processes' groups for the block (their master watch cannot run)."""
    for proc in procs:
        os.killpg(proc.pid, signal.SIGSTOP)
    try:
        yield
    finally:
        for proc in procs:
            os.killpg(proc.pid, signal.SIGCONT)


def providers(ros, kind, name):
    """Nodes the master lists for topic/service `name`; kind 0 publishers, 1 subscribers,
    2 services."""
    return next((nodes for entry, nodes in ros.system_state()[kind] if entry == name), [])


def wait_registered(ros, kind, name, node, proc=None):
    """Until the master lists `node` for `name`; on a time-out, with `proc`'s output and its
    threads' stacks (where its master watch is stuck, if it is)."""
    try:
        ros.wait_for(lambda: node in providers(ros, kind, name), TIMEOUT, f"{node} on {name}")
    except AssertionError as error:
        if proc is None:
            raise
        raise AssertionError(f"{error}\n{ros.output(proc)}\n{thread_stacks(proc)}") from None


def thread_stacks(proc):
    """Every thread's backtrace of `proc`'s node (the newest process of its group), by gdb."""
    gdb = shutil.which("gdb")
    if gdb is None:
        return "(no gdb for the threads' stacks)"
    pids = subprocess.run(["pgrep", "-g", str(proc.pid)], capture_output=True, text=True)
    node = max((int(p) for p in pids.stdout.split()), default=proc.pid)
    command = [gdb, "-p", str(node), "-batch", "-ex", "thread apply all bt"]
    try:
        return subprocess.run(command, capture_output=True, text=True, timeout=120).stdout
    except subprocess.TimeoutExpired:
        return "(gdb did not finish)"


def test_python_nodes_register_again_with_a_new_master(ros):
    talker = ros.start(["rosrun", "basics", "talker.py"], name="talker")
    listener = ros.start(["rosrun", "basics", "listener.py"], name="listener")
    server = ros.start(["rosrun", "basics", "service_server.py"], name="service_server")
    wait_registered(ros, 0, "/chatter", "/talker")
    wait_registered(ros, 1, "/chatter", "/listener")
    wait_registered(ros, 2, "/word_count", "/service_server")

    with stopped(talker, listener, server):
        restart_master(ros)
        assert providers(ros, 0, "/chatter") == []  # the new master knows nobody yet
        # A new subscriber before the talker is back, a new publisher before the listener.
        probe = ros.probe(["/chatter"], ready=False, types={"/chatter": "std_msgs/String"})
        ros.start(
            ["rostopic", "pub", "-r", "10", "/chatter", "std_msgs/String", "data: after restart"],
            name="new_publisher",
        )
        ros.wait_for(lambda: len(providers(ros, 1, "/chatter")) == 1, TIMEOUT, "the probe")
        ros.wait_for(lambda: len(providers(ros, 0, "/chatter")) == 1, TIMEOUT, "rostopic pub")

    wait_registered(ros, 0, "/chatter", "/talker")
    wait_registered(ros, 1, "/chatter", "/listener")
    wait_registered(ros, 2, "/word_count", "/service_server")
    wait_registered(ros, 0, "/rosout", "/talker")  # its log reaches the new rosout
    ros.wait_for(
        lambda: any(m["msg"]["data"].startswith("hello world") for m in probe.messages()),
        TIMEOUT,
        "the talker's messages at the new subscriber",
    )
    ros.wait_for(
        lambda: "I heard after restart" in ros.output(listener),
        TIMEOUT,
        "the new publisher's messages at the listener",
    )
    nodes = ros.run(["rosnode", "list"]).stdout.split()
    assert {"/talker", "/listener", "/service_server"} <= set(nodes)
    answer = ros.run(["rosservice", "call", "/word_count", "words: 'one two three'"]).stdout
    assert answer.strip() == "count: 3"
    for proc in (talker, listener, server):
        assert_registered_again_once(ros, proc)


def test_simulator_registers_again_with_a_new_master(ros):
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    sim = ros.start(
        # stdbuf: roscpp's log lines reach the log file as they are written.
        ["stdbuf", "-oL", "rosrun", "bullet_turtlebot", "simulator", "_world:=playground"],
        name="simulator",
    )
    wait_registered(ros, 0, "/odom", "/simulator")
    wait_registered(ros, 2, "/simulator/pause", "/simulator")
    teleop = "/cmd_vel_mux/input/teleop"

    with stopped(sim):
        restart_master(ros)
        assert not ros.master().hasParam("/roskit", "/use_sim_time")[2]
        # A new subscriber before the simulator is back, a new publisher before it too.
        odom = ros.probe(["/odom"], ready=False, types={"/odom": "nav_msgs/Odometry"})
        ros.start(
            ["rostopic", "pub", "-r", "10", teleop, "geometry_msgs/Twist", "linear: {x: 0.3}"],
            name="new_publisher",
        )
        ros.wait_for(lambda: providers(ros, 1, "/odom"), TIMEOUT, "the probe")
        ros.wait_for(lambda: providers(ros, 0, teleop), TIMEOUT, "rostopic pub")

    wait_registered(ros, 0, "/odom", "/simulator", sim)
    wait_registered(ros, 1, teleop, "/simulator", sim)
    wait_registered(ros, 2, "/simulator/pause", "/simulator", sim)
    # The new subscriber gets odometry, and it moves: the new publisher reached the simulator.
    ros.wait_for(
        lambda: any(m["msg"]["twist"]["twist"]["linear"]["x"] > 0.1 for m in odom.messages()),
        TIMEOUT,
        "odometry of the commanded motion at the new subscriber",
    )
    assert "/simulator" in ros.run(["rosnode", "list"]).stdout.split()
    ros.run(["rosservice", "call", "/simulator/pause"])
    ros.run(["rosservice", "call", "/simulator/unpause"])
    master = ros.master()
    assert master.getParam("/roskit", "/use_sim_time")[2] is True
    assert master.getParam("/roskit", "/simulator/world")[2] == "playground"
    assert_registered_again_once(ros, sim)


def test_live_mapping_goes_on_across_a_master_restart(ros):
    """The chapter 9 set-up (simulator and slam_gmapping, both C++) keeps mapping, and
    map_saver started against the new master saves the map."""
    ros.start(
        ["roslaunch", "bullet_turtlebot", "simulator.launch", "world:=playground", "speed:=2"],
        name="simulator",
    )
    ros.wait_for_topic("scan", timeout=TIMEOUT)
    # A 20 m square map (the default is 200 m: 16 MB a message) around the playground.
    params = {"base_frame": "base_footprint", "map_update_interval": 1.0}
    params.update({"xmin": -10, "xmax": 10, "ymin": -10, "ymax": 10})
    for name, value in params.items():
        ros.run(["rosparam", "set", f"/slam_gmapping/{name}", str(value)])
    slam = ros.start(
        ["stdbuf", "-oL", "rosrun", "gmapping_lite", "slam_gmapping"], name="slam_gmapping"
    )
    before = ros.echo("map", timeout=TIMEOUT)[0]["msg"]["header"]["stamp"]

    restart_master(ros)
    wait_registered(ros, 0, "/map", "/slam_gmapping")
    wait_registered(ros, 1, "/scan", "/slam_gmapping")
    wait_registered(ros, 2, "/dynamic_map", "/slam_gmapping")
    wait_registered(ros, 0, "/scan", "/simulator")
    ros.wait_for(
        lambda: ros.master().getParam(CALLER_ID, "/use_sim_time")[2] is True,
        TIMEOUT,
        "/use_sim_time put back by the simulator (the clock)",
    )
    # Turning makes slam_gmapping process scans, so its map updates go on.
    ros.start(
        ["rostopic", "pub", "-r", "10", "/cmd_vel_mux/input/teleop", "geometry_msgs/Twist"]
        + ["angular: {z: 0.8}"],
        name="turn",
    )
    maps = ros.probe(["/map"], ready=False, types={"/map": "nav_msgs/OccupancyGrid"})
    ros.wait_for(
        lambda: any(m["msg"]["header"]["stamp"] > before for m in maps.messages()),
        TIMEOUT,
        "a map made after the restart",
    )
    saved = ros.run(["rosrun", "map_server", "map_saver", "-f", "after_restart"], timeout=90)
    assert (ros.workdir / "after_restart.pgm").exists(), saved.stdout + saved.stderr
    assert (ros.workdir / "after_restart.yaml").exists()
    assert_registered_again_once(ros, slam)
