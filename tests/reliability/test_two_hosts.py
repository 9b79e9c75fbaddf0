"""The book's chapter 9 set-up across two hosts: two network namespaces joined by a veth pair
stand in for two machines. Host A runs roscore and the simulator, host B slam_gmapping and
map_saver, each node with ROS_IP set to its own host's address (ROS_HOSTNAME unset), and B's
ROS_MASTER_URI pointing at A. The map B saves must show the walls A simulates, and the
simulator must list slam_gmapping, at B's address, among the subscribers of its scans.

Needs root (`ip netns add`); skipped, saying why, without it. The robot does not drive:
slam_gmapping publishes its first map from its first scan, which is all map_saver needs."""

import json
import os
import shutil
import signal
import subprocess
import sys

import pytest
from rosbook_env.geometry import yaw_of
from rosbook_eval.grids import near_wall_share, occupied_points
from rosbook_eval.poses import compose, inverse
from rosbook_eval.scoring import DEFAULT_TOLERANCE, place_grid
from rosbook_eval.truth import TRUTH_RESOLUTION, load_grid
from roskit import PROBE, RosGraph, kill_tree, read_jsonl, ros_environment, wait_until

SUBNET = "10.77.0"  # private; each namespace has its own stack, so runs do not clash
HOST_A, HOST_B = f"{SUBNET}.1", f"{SUBNET}.2"
MASTER_URI = f"http://{HOST_A}:11311"  # a fresh namespace: the default port is free
WORLD = "playground"  # a 12 m x 10 m room: the 8 m laser sees walls all around the start
CALLER = "/test_two_hosts"
# slam_gmapping as the book's chapter 9 runs it on a Turtlebot (see test_slam_simulator.py);
# the map bounds keep the one-scan map small.
SLAM_PARAMS = {"base_frame": "base_footprint", "maxUrange": 6.0, "xmin": -10, "xmax": 10}
SLAM_PARAMS.update({"ymin": -10, "ymax": 10})

# One XML-RPC call to a ROS API, made inside a namespace (this process cannot reach it):
# argv is the URI, the method and its arguments after the caller id, as JSON.
XMLRPC_CALL = (
    "import json, sys, xmlrpc.client\n"
    "proxy = xmlrpc.client.ServerProxy(sys.argv[1])\n"
    "print(json.dumps(getattr(proxy, sys.argv[2])(*json.loads(sys.argv[3]))))\n"
)


def run_ip(*args):
    return subprocess.run(["ip", *args], capture_output=True, text=True, timeout=30)


def netns_problem():
    """Why two namespaces cannot be made here (None when they can)."""
    if os.geteuid() != 0:
        return "needs root to create network namespaces (ip netns add)"
    if shutil.which("ip") is None:
        return "needs iproute2's `ip` command"
    probe = f"rbprobe{os.getpid()}"
    done = run_ip("netns", "add", probe)
    if done.returncode != 0:
        return f"`ip netns add` does not work here: {done.stderr.strip()}"
    run_ip("netns", "del", probe)
    return None


class Host:
    """A network namespace with one address on the veth link, and the ROS processes in it."""

    def __init__(self, name, address, workdir):
        self.name, self.address, self.workdir = name, address, workdir
        env = ros_environment(11311)
        env.pop("ROS_HOSTNAME")  # it would win over ROS_IP
        env.update(ROS_MASTER_URI=MASTER_URI, ROS_IP=address)
        self.env = env
        self.procs = []

    def command(self, cmd):
        return ["ip", "netns", "exec", self.name, *cmd]

    def start(self, cmd, label):
        log = open(self.workdir / f"{self.name}-{label}.log", "w")
        proc = subprocess.Popen(
            self.command(cmd),
            stdout=log,
            stderr=subprocess.STDOUT,
            stdin=subprocess.DEVNULL,
            env=self.env,
            cwd=self.workdir,
            start_new_session=True,  # its own process group: stopped with its children
        )
        proc.log_path = log.name
        self.procs.append(proc)
        return proc

    def run(self, cmd, timeout=120):
        return subprocess.run(
            self.command(cmd),
            capture_output=True,
            text=True,
            timeout=timeout,
            env=self.env,
            cwd=self.workdir,
            stdin=subprocess.DEVNULL,
        )

    def call(self, uri, method, *args):
        """An XML-RPC call from this host; None when nothing answers (yet)."""
        cmd = [sys.executable, "-c", XMLRPC_CALL, uri, method, json.dumps([CALLER, *args])]
        done = self.run(cmd, timeout=30)
        return json.loads(done.stdout) if done.returncode == 0 else None

    def stop_all(self):
        for proc in self.procs:
            if proc.poll() is None:
                try:
                    os.killpg(proc.pid, signal.SIGINT)
                except ProcessLookupError:
                    pass
        for proc in self.procs:
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                kill_tree(proc)


@pytest.fixture
def two_hosts(tmp_path):
    problem = netns_problem()
    if problem:
        pytest.skip(problem)
    tag = f"rb{os.getpid() % 100000}"  # names unique per run; an interface name has <= 15 chars
    a, b = Host(f"{tag}a", HOST_A, tmp_path), Host(f"{tag}b", HOST_B, tmp_path)
    try:
        for host in (a, b):
            assert run_ip("netns", "add", host.name).returncode == 0
        link = run_ip("link", "add", f"{tag}va", "type", "veth", "peer", "name", f"{tag}vb")
        assert link.returncode == 0, link.stderr
        for host, device in ((a, f"{tag}va"), (b, f"{tag}vb")):
            steps = [
                ["link", "set", device, "netns", host.name],
                ["-n", host.name, "addr", "add", f"{host.address}/24", "dev", device],
                ["-n", host.name, "link", "set", device, "up"],
                ["-n", host.name, "link", "set", "lo", "up"],  # nodes on one host talk over it
            ]
            for step in steps:
                done = run_ip(*step)
                assert done.returncode == 0, f"ip {' '.join(step)}: {done.stderr}"
        yield a, b
    finally:
        for host in (b, a):
            host.stop_all()
        for host in (a, b):
            run_ip("netns", "del", host.name)  # takes its end of the veth pair with it
        run_ip("link", "del", f"{tag}va")  # only there if it never reached a namespace


def wait_for(predicate, what, timeout=90):
    wait_until(predicate, timeout, what, interval=0.5)


output = RosGraph.output  # a started process's log


def pose_of(message):
    p = message["pose"]["pose"]
    return (p["position"]["x"], p["position"]["y"], yaw_of(p["orientation"]))


def scan_subscribers(host_a, host_b):
    """The simulator's outgoing /scan connections, from its own bus information:
    [(subscriber's node name, transport description)]."""
    code, _, uri = host_b.call(MASTER_URI, "lookupNode", "/simulator") or (0, "", "")
    if code != 1:
        return []
    answer = host_a.call(uri, "getBusInfo")
    if not answer or answer[0] != 1:
        return []
    # Each: [id, peer, direction, transport, topic, connected, info]
    return [(c[1], c[-1]) for c in answer[2] if c[2] == "o" and c[4] == "/scan"]


def test_chapter9_mapping_across_two_hosts(two_hosts, tmp_path):
    host_a, host_b = two_hosts
    # The world's true walls need no ROS: drawn meanwhile, in this (the root) namespace.
    truth_cmd = ["rosrun", "bullet_turtlebot", "world_to_map", WORLD, "-f", str(tmp_path / "truth")]
    truth_cmd += ["--resolution", str(TRUTH_RESOLUTION)]
    truth_map = subprocess.Popen(
        truth_cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True
    )
    host_b.procs.append(truth_map)  # stopped with the rest if the test fails first
    core = host_a.start(["roscore", "-p", "11311"], "roscore")

    def master_answers_host_b():
        assert core.poll() is None, output(core)
        return (host_b.call(MASTER_URI, "getParam", "/run_id") or [0])[0] == 1

    wait_for(master_answers_host_b, f"host B to reach the master at {MASTER_URI}")

    sim = host_a.start(
        ["roslaunch", "bullet_turtlebot", "simulator.launch", f"world:={WORLD}"], "simulator"
    )

    def published(topic):
        assert sim.poll() is None, output(sim)
        state = host_b.call(MASTER_URI, "getSystemState")
        return state is not None and any(name == topic for name, _ in state[2][0])

    # Once the simulator publishes, /use_sim_time is set: slam_gmapping will run on sim time.
    wait_for(lambda: published("/scan"), "the simulator's /scan")

    # Where the odometry frame (and so SLAM's map frame) lies in the world, seen from host A;
    # meanwhile host B maps and saves.
    poses = tmp_path / "start.jsonl"
    topics = ["/base_pose_ground_truth", "/odom"]
    probe_cmd = [sys.executable, str(PROBE), "--out", str(poses), "--count", "1"]
    probe = host_a.start([*probe_cmd, "--timeout", "120", *topics], "probe")
    slam_args = [f"_{name}:={value}" for name, value in SLAM_PARAMS.items()]
    slam = host_b.start(["rosrun", "gmapping_lite", "slam_gmapping", *slam_args], "slam")
    saver_cmd = ["rosrun", "map_server", "map_saver", "-f", str(tmp_path / "map")]
    saver = host_b.start([*saver_cmd, "--timeout", "120"], "map_saver")

    assert saver.wait(timeout=150) == 0, output(saver) + output(slam)
    assert probe.wait(timeout=150) == 0, output(probe)
    first = {m["topic"]: m["msg"] for m in read_jsonl(poses)}
    odom_in_world = compose(
        pose_of(first["/base_pose_ground_truth"]), inverse(pose_of(first["/odom"]))
    )

    # The simulator, on host A, serves its scans to slam_gmapping at host B's address.
    subscribers = []

    def slam_subscribed():
        subscribers[:] = scan_subscribers(host_a, host_b)
        return any(peer == "/slam_gmapping" for peer, _ in subscribers)

    wait_for(slam_subscribed, "the simulator to list slam_gmapping on /scan", timeout=60)
    info = [info for peer, info in subscribers if peer == "/slam_gmapping"]
    assert HOST_B in info[0], subscribers
    assert slam.poll() is None, output(slam)  # still mapping after the save

    slam_map = load_grid(tmp_path / "map.yaml")
    cells = slam_map[0]
    assert (cells == 0).sum() > 100 and (cells >= 65).sum() > 50, "free and walls both mapped"
    assert truth_map.wait(timeout=120) == 0, truth_map.stdout.read().decode()
    truth = load_grid(tmp_path / "truth.yaml")
    walls = occupied_points(place_grid(slam_map, odom_in_world))
    share = near_wall_share(walls, truth, DEFAULT_TOLERANCE)
    assert share >= 0.9, f"{share:.0%} of the mapped walls lie on the world's walls"
