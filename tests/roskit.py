"""Test helpers that drive real ROS: a private master on a free port (the processes roscore
runs), real nodes as subprocesses, a probe that records topics to JSON lines, and rostest runs.

Every process started through a RosGraph is killed (with its process group) when the
graph is closed, so a failing test leaves nothing running.
"""

import atexit
import functools
import hashlib
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import uuid
import xmlrpc.client
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
PROBE = Path(__file__).resolve().parent / "tools" / "topic_probe.py"
CLOCK_WATCH = PROBE.with_name("clock_watch.py")
DEBIAN_PYTHON = "/usr/bin/python3"
CALLER_ID = "/roskit"


def free_port():
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


# The xdist workers share what rosrun answered through files in this folder (set by the first
# process that imports roskit, the controller, and inherited by the workers it starts).
SHARED_ROSRUN_ANSWERS = "ROSKIT_ROSRUN_ANSWERS"


@functools.lru_cache(maxsize=None)
def _rosrun_target(package, executable, prefix_path, package_path):
    """The file `rosrun PACKAGE EXECUTABLE` runs, asked of rosrun itself (`--prefix echo`
    prints it instead of running it), or None where rosrun finds no single file. One worker
    asks; the others read its answer."""
    answers = os.environ.get(SHARED_ROSRUN_ANSWERS)
    key = hashlib.sha1("\0".join((package, executable, prefix_path, package_path)).encode())
    answer = Path(answers, key.hexdigest()) if answers and os.path.isdir(answers) else None
    if answer is not None and answer.exists():
        path = answer.read_text()
        return path if _runnable(path) else None
    found = subprocess.run(
        ["rosrun", "--prefix", "echo", package, executable],
        capture_output=True,
        text=True,
        stdin=subprocess.DEVNULL,
        env={**os.environ, "CMAKE_PREFIX_PATH": prefix_path, "ROS_PACKAGE_PATH": package_path},
    )
    path = found.stdout.strip() if found.returncode == 0 else ""
    if answer is not None:
        partial = answer.with_name(f"{answer.name}.{os.getpid()}")
        partial.write_text(path)
        os.replace(partial, answer)  # readers see a whole answer or none
    return path if _runnable(path) else None


def _runnable(path):
    return bool(path) and os.path.isfile(path) and os.access(path, os.X_OK)


def without_rosrun(cmd, env):
    """`cmd` with a leading `rosrun PACKAGE EXECUTABLE` replaced by the file rosrun would run,
    found once per worker and workspace: rosrun's search (catkin_find, rospack, find) costs a
    third of a CPU second per call, and the suite makes hundreds. Anything else (a shell
    string, rosrun's options, a name rosrun cannot resolve to one file) is left to rosrun, so
    its own errors still show."""
    if isinstance(cmd, str) or len(cmd) < 3 or cmd[0] != "rosrun" or cmd[1].startswith("-"):
        return cmd
    path = _rosrun_target(
        cmd[1], cmd[2], env.get("CMAKE_PREFIX_PATH", ""), env.get("ROS_PACKAGE_PATH", "")
    )
    return cmd if path is None else [path, *cmd[3:]]


def launched_from_shell(ros, tmp_path):
    """The folders of `cd shell && roslaunch ...`: roslaunch runs its nodes in ROS_HOME
    (~/.ros) and leaves $PWD as the shell's folder. Returns (shell, ros_home, env)."""
    shell, ros_home = tmp_path / "shell", tmp_path / "ros_home"
    shell.mkdir()
    ros_home.mkdir()
    env = {**ros.env, "PWD": str(shell), "ROS_HOME": str(ros_home)}
    return shell, ros_home, env


def run_in_ros_home(cmd, env, ros_home):
    """Run a `rosrun PACKAGE NODE ...` command as roslaunch runs the node: its file itself (rosrun
    is a bash script, and bash resets $PWD to its cwd), in `ros_home`; output captured."""
    return subprocess.run(
        without_rosrun(cmd, env),
        env=env,
        cwd=ros_home,
        capture_output=True,
        text=True,
        timeout=120,
    )


def launch_node_list(launch_args, env):
    """The node names `roslaunch --nodes LAUNCH_ARGS` prints under `env`, from roslaunch's own
    loader in this process: a roslaunch process costs over a CPU second to start, and the
    suite asks this some fifty times. Substitutions ($(optenv), <param command=...>) see
    `env`. Raises roslaunch's RLException where the command would exit 1."""
    from roslaunch import config, node_args, rlutil, xmlloader

    saved = dict(os.environ)
    os.environ.clear()
    os.environ.update(env)
    try:
        # roslaunch reads `name:=value` arguments from sys.argv: hand them over with each file.
        files = rlutil.resolve_launch_arguments(list(launch_args))
        loaded = config.load_config_default(
            [(path, ["roslaunch", *launch_args]) for path in files],
            None,
            loader=xmlloader.XmlLoader(resolve_anon=False),
            verbose=False,
            assign_machines=False,
        )
        return node_args.get_node_list(loaded)
    finally:
        os.environ.clear()
        os.environ.update(saved)


@functools.lru_cache(maxsize=None)
def _process_log_dir():
    """One ROS log folder for this process's graphs that have no folder of their own, removed
    when the process ends (a folder per graph left some 250 in /tmp per suite run)."""
    folder = tempfile.mkdtemp(prefix="roslog-")
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    return folder


def ros_environment(port, base=None, log_dir=None):
    """The environment for nodes of a master on `port`: `base` (default: this process's, set
    up by devel/setup.bash) with the master's address and test-friendly logging. ROS's log
    files go to `log_dir`, else to base's ROS_LOG_DIR, else to a folder removed at exit."""
    env = dict(os.environ if base is None else base)
    if "ROS_PACKAGE_PATH" not in env:
        raise RuntimeError(
            "ROS environment missing: run the tests with `make test`, or "
            "`source catkin_ws/devel/setup.bash` first"
        )
    env["ROS_MASTER_URI"] = f"http://127.0.0.1:{port}"
    env["ROS_HOSTNAME"] = "127.0.0.1"
    env["PYENV_VERSION"] = "system"
    env["PYTHONUNBUFFERED"] = "1"
    env["ROSCONSOLE_FORMAT"] = "[${severity}] [${node}]: ${message}"
    env["ROS_LOG_DIR"] = str(log_dir or env.get("ROS_LOG_DIR") or _process_log_dir())
    return env


# What rosmaster prints (rosgraph.xmlrpc) when it cannot bind its port; it then stays up unserved.
PORT_TAKEN = "Unable to start XML-RPC server"


class PortTaken(RuntimeError):
    """rosmaster could not bind its port."""


class RosGraph:
    """A roscore on a free port plus the processes a test starts against it."""

    def __init__(self, workdir, base_env=None):
        self.workdir = Path(workdir)
        self.procs = []
        self._log_index = 0
        self._clock_file = None
        try:
            self._start_core(base_env)
        except BaseException:
            self.close()
            raise

    def _start_core(self, base_env):
        # What roscore runs (its launch file roslaunch/roscore.xml): rosmaster --core -w 3, the
        # /run_id roslaunch sets, and rosout; started directly, because roscore's roslaunch
        # around them costs most of a CPU second per test on a two-core machine.
        # The free port can be taken before rosmaster binds it (another worker's master, or an
        # outgoing connection's local port: both come from the same ephemeral range), and then
        # rosmaster stays up without serving: it is started again on another port.
        # ROS's own log files beside the test's other outputs (pytest prunes old runs).
        log_dir = self.workdir / "ros_log"
        log_dir.mkdir(parents=True, exist_ok=True)
        for attempt in range(3):
            self.port = free_port()
            self.env = ros_environment(self.port, base_env, log_dir=log_dir)
            cmd = ["rosmaster", "--core", "-p", str(self.port), "-w", "3"]
            self.core = self.start(cmd, name="rosmaster")
            try:
                self.wait_for_master(until=lambda master: master.getPid(CALLER_ID)[0] == 1)
                break
            except PortTaken:
                _kill_groups([self.core], 5)
                if attempt == 2:
                    raise
        self.master().setParam(CALLER_ID, "/run_id", str(uuid.uuid1()))
        # start() runs the file rosrun resolves, asked once per run (without_rosrun).
        rosout = self.start(["rosrun", "rosout", "rosout", "__name:=rosout"], name="rosout")
        # Up before the test goes on, as a test expects of roscore: else rosout could read a
        # /use_sim_time the test sets and add itself to /clock's subscribers.
        self.wait_for_master(
            until=lambda master: (
                rosout.poll() is None
                and ["/rosout_agg", "rosgraph_msgs/Log"]
                in master.getPublishedTopics(CALLER_ID, "")[2]
            )
        )

    # -- processes ---------------------------------------------------------------
    def start(self, cmd, name=None, stdin=None, env=None, cwd=None):
        """Start a command (list or shell string); its output goes to a log file."""
        self._log_index += 1
        label = name or (cmd if isinstance(cmd, str) else Path(cmd[0]).name)
        log_path = self.workdir / f"{self._log_index:02d}-{_safe(label)}.log"
        log = open(log_path, "w")
        proc = subprocess.Popen(
            without_rosrun(cmd, env or self.env),
            shell=isinstance(cmd, str),
            stdout=log,
            stderr=subprocess.STDOUT,
            stdin=stdin if stdin is not None else subprocess.DEVNULL,
            env=env or self.env,
            cwd=cwd or self.workdir,
            start_new_session=True,
        )
        proc.log_path = log_path
        proc.label = label
        self.procs.append(proc)
        return proc

    def run(self, cmd, timeout=120, check=True, input=None, cwd=None):
        """Run a command to completion; returns CompletedProcess with text output. The
        timeout only catches a hang: on a loaded machine even `roslaunch --nodes` (a few
        rospack calls) has taken over 30 s."""
        done = subprocess.run(
            without_rosrun(cmd, self.env),
            shell=isinstance(cmd, str),
            capture_output=True,
            text=True,
            timeout=timeout,
            env=self.env,
            cwd=cwd or self.workdir,
            input=input,
        )
        if check and done.returncode != 0:
            raise AssertionError(
                f"{cmd!r} exited {done.returncode}\nstdout:\n{done.stdout}\nstderr:\n{done.stderr}"
            )
        return done

    @staticmethod
    def output(proc):
        return Path(proc.log_path).read_text(errors="replace")

    def stop(self, proc, sig=signal.SIGINT, timeout=10):
        if proc.poll() is None:
            try:
                os.killpg(proc.pid, sig)
                proc.wait(timeout=timeout)
            except (ProcessLookupError, subprocess.TimeoutExpired):
                kill_tree(proc)
        return proc.returncode

    def close(self, timeout=5):
        """End the test's graph: every process it started, with what roslaunch started below
        them, killed at once. The test is over, so nothing is left to hear a clean Ctrl-C
        (each rospy node would spend most of a second on it), and the master goes too: no
        registration outlives it. Tests that check a node's Ctrl-C use `stop`."""
        _kill_groups([p for p in self.procs if p.poll() is None], timeout)

    # -- waiting -----------------------------------------------------------------
    def master(self):
        """The master's XML-RPC API, asked in-process: polling it costs no process start-up,
        which matters when a loaded machine makes every `rostopic` call take a second."""
        return xmlrpc.client.ServerProxy(self.env["ROS_MASTER_URI"], transport=_QuickTransport())

    def wait_for_master(self, timeout=60, until=None):
        """Until the master answers `until(master)` (default: /run_id is set, which roscore
        does once it is up)."""
        if until is None:
            until = lambda master: master.getParam(CALLER_ID, "/run_id")[0] == 1  # noqa: E731
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.core.poll() is not None:
                raise RuntimeError("the master died:\n" + self.output(self.core))
            output = self.output(self.core)
            if PORT_TAKEN in output:
                raise PortTaken(output)
            try:
                if until(self.master()):
                    return
            except (OSError, xmlrpc.client.Error):
                pass
            time.sleep(0.1)
        raise TimeoutError(
            f"roscore did not answer within {timeout} s; rosmaster's output:\n"
            + self.output(self.core)[-2000:]
        )

    def system_state(self):
        """[publishers, subscribers, services], each [[name, [node, ...]], ...]."""
        code, message, state = self.master().getSystemState(CALLER_ID)
        if code != 1:
            raise RuntimeError(f"getSystemState: {message}")
        return state

    def wait_for(self, predicate, timeout=20, what="condition", interval=0.1):
        wait_until(predicate, timeout, what, interval)

    def topics(self):
        """Every topic with a publisher or a subscriber (what `rostopic list` prints)."""
        publishers, subscribers, _ = self.system_state()
        return {name for name, _ in publishers + subscribers}

    def services(self):
        return {name for name, _ in self.system_state()[2]}

    def subscribes(self, node, *topics):
        """True once the master lists `node` as a subscriber of every topic."""
        subscribers = dict(self.system_state()[1])
        return all(node in subscribers.get(topic, []) for topic in topics)

    def wait_for_topic(self, topic, timeout=60):
        topic = "/" + topic.lstrip("/")
        self.wait_for(lambda: topic in self.topics(), timeout, f"topic {topic}")

    def wait_for_service(self, service, timeout=60):
        service = "/" + service.lstrip("/")
        self.wait_for(lambda: service in self.services(), timeout, f"service {service}")

    # -- topics --------------------------------------------------------------------
    def probe(
        self, topics, count=None, duration=None, timeout=30, name=None, ready=True, types=None
    ):
        """Start recording `topics` (list of names) in a subprocess; returns a Probe.

        With ready=True, wait until the probe is connected to every topic's publisher
        (so the publishers must exist); with ready=False, return at once. `types`
        ({topic: "pkg/Msg"}) subscribes at once, before any publisher is known.
        """
        probe = Probe(self, topics, count, duration, timeout, name, types or {})
        if ready:
            probe.wait_ready()
        return probe

    def sim_time(self, timeout=60):
        """The newest /clock in seconds, one that arrived after this call (as `echo` would
        give). The first call starts a watcher node (tools/clock_watch.py) that keeps it in a
        file, so a test polling the clock does not start a probe process per look."""
        if self._clock_file is None:
            self._clock_file = self.workdir / f"clock-{self._log_index + 1:02d}.txt"
            self.start([DEBIAN_PYTHON, str(CLOCK_WATCH), str(self._clock_file)], name="clock_watch")
        before = _read_clock(self._clock_file)
        since = before[0] if before else 0
        found = []

        def newer():
            now = _read_clock(self._clock_file)
            if now and now[0] > since:
                found.append(now[1])
                return True
            return False

        self.wait_for(newer, timeout, "a /clock message", interval=0.02)
        return found[-1]

    def echo(self, topic, count=1, timeout=30):
        """Block until `count` messages of `topic` arrive; return them as dicts."""
        probe = self.probe([topic], count=count, timeout=timeout)
        return probe.wait(timeout + 10)


class Probe:
    """Records messages as JSON lines: {"topic", "wall", "ros", "msg"}."""

    def __init__(self, graph, topics, count, duration, timeout, name, types):
        self.graph = graph
        self.out = graph.workdir / f"probe-{graph._log_index + 1:02d}.jsonl"
        cmd = [DEBIAN_PYTHON, str(PROBE), "--out", str(self.out), "--timeout", str(timeout)]
        if count is not None:
            cmd += ["--count", str(count)]
        if duration is not None:
            cmd += ["--duration", str(duration)]
        if name:
            cmd += ["--name", name]
        cmd += [f"--type={topic}={msg_type}" for topic, msg_type in types.items()]
        self.proc = graph.start(cmd + list(topics), name="probe")
        self.timeout = timeout

    def wait_ready(self):
        ready = self.out.with_suffix(".ready")

        def connected():
            if self.proc.poll() not in (None, 0):
                raise AssertionError("probe failed:\n" + self.graph.output(self.proc))
            return ready.exists()

        self.graph.wait_for(connected, self.timeout, "probe to connect")

    def messages(self):
        return read_jsonl(self.out)

    def wait(self, timeout=60):
        try:
            self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.graph.stop(self.proc)
        if self.proc.returncode not in (0, None):
            raise AssertionError(
                f"probe failed ({self.proc.returncode}):\n" + self.graph.output(self.proc)
            )
        return self.messages()

    def stop(self):
        self.graph.stop(self.proc)
        return self.messages()


def _read_clock(path):
    """(sequence, seconds) from clock_watch's file, or None before its first write."""
    try:
        sequence, seconds = Path(path).read_text().split()
    except (FileNotFoundError, ValueError):
        return None
    return int(sequence), float(seconds)


def read_jsonl(path):
    """Every complete JSON-lines record in `path` so far ([] if it does not exist yet). A
    writer may be in the middle of the last line while we read: only lines that end in a
    newline are whole, so a partial tail is left for the next read."""
    path = Path(path)
    if not path.exists():
        return []
    text = path.read_text()
    complete = text[: text.rfind("\n") + 1]
    return [json.loads(line) for line in complete.splitlines() if line.strip()]


def run_rostest(package, test_file, timeout=300, extra_args=()):
    """Run `rostest package test_file` (its own master on a free port); return output."""
    env = ros_environment(free_port())
    done = subprocess.run(
        ["rostest", package, test_file, *extra_args],
        capture_output=True,
        text=True,
        timeout=timeout,
        env=env,
    )
    output = done.stdout + done.stderr
    if done.returncode != 0:
        raise AssertionError(f"rostest {package} {test_file} exited {done.returncode}\n{output}")
    return output


class _QuickTransport(xmlrpc.client.Transport):
    """XML-RPC with a socket timeout, so a master that stopped answering cannot hang a test."""

    def make_connection(self, host):
        connection = super().make_connection(host)
        connection.timeout = 10
        return connection


def _safe(label):
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in str(label))[:40]


def wait_until(predicate, timeout=20, what="condition", interval=0.1):
    """Poll `predicate` until true; a wall-time limit, only there to catch a hang."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return
        time.sleep(interval)
    raise AssertionError(f"timed out after {timeout} s waiting for {what}")


def descendants(pid):
    """{pid: command line} of every process below `pid` (from /proc)."""
    return descendants_of([pid])


def _stat_fields(stat_path):
    """The fields of /proc/PID/stat after the command name (which may hold spaces and
    parentheses): [0] the state, [1] the parent's pid, [2] the process group."""
    return Path(stat_path).read_text().rsplit(")", 1)[1].split()


def descendants_of(pids):
    """{pid: command line} of every process below any of `pids` (one look at /proc)."""
    children = {}
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            ppid = int(_stat_fields(stat)[1])
            cmdline = (stat.parent / "cmdline").read_bytes().replace(b"\0", b" ").decode()
        except (OSError, IndexError, ValueError):
            continue  # a process that ended while we looked
        children.setdefault(ppid, []).append((int(stat.parent.name), cmdline))
    found, todo = {}, list(pids)
    while todo:
        for child, cmdline in children.get(todo.pop(), []):
            found[child] = cmdline
            todo.append(child)
    return found


def kill_tree(proc):
    """SIGKILL `proc`, its process group and every process below it (roslaunch's nodes run
    in sessions of their own)."""
    _kill_groups([proc])


def _running(pid):
    """True while `pid` runs (a zombie has ended: its parent has yet to collect it)."""
    try:
        state = _stat_fields(f"/proc/{pid}/stat")[0]
    except (OSError, IndexError):
        return False
    return state != "Z"


def _stop_x_servers(below, timeout=5.0):
    """Let the X servers (xvfb-run's Xvfb) among `below` ({pid: command line}) exit on
    SIGTERM: Xvfb removes its /tmp/.X<n>-lock as it exits, and SIGKILL would leave it."""
    servers = [
        pid for pid, cmdline in below.items() if Path(cmdline.split(" ", 1)[0]).name == "Xvfb"
    ]
    for pid in servers:
        try:
            os.kill(pid, signal.SIGTERM)
        except ProcessLookupError:
            pass
    deadline = time.monotonic() + timeout
    while any(_running(pid) for pid in servers) and time.monotonic() < deadline:
        time.sleep(0.05)  # a poll with a deadline: whatever is left is killed next


def _kill_groups(procs, timeout=5):
    # roslaunch starts each node in a session of its own: killed with roslaunch's group, they
    # would live on (waiting for their master) unless killed by pid as well.
    below = descendants_of([proc.pid for proc in procs])
    _stop_x_servers(below)
    for proc in procs:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    for pid in below:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    for proc in procs:
        try:
            proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            print(f"could not kill {proc.args!r}", file=sys.stderr)
