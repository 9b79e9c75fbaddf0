"""Helpers for the simulator's integration tests: worlds written on the fly, a simulator
started in sim time, and reading probe records."""

import subprocess
from pathlib import Path

from rosbook_env.geometry import yaw_of

HERE = Path(__file__).resolve().parent
DRIVE = HERE / "drive_node.py"
DEBIAN_PYTHON = "/usr/bin/python3"


def write_pgm(path, rows):
    """rows: list of equal-length lists of grey values (0..255), row 0 = top."""
    height, width = len(rows), len(rows[0])
    data = bytes(v for row in rows for v in row)
    Path(path).write_bytes(b"P5\n%d %d\n255\n" % (width, height) + data)


def write_world(directory, name="world", boxes=(), cylinders=(), start=None, extra=""):
    """A primitives-only world YAML; boxes are (x, y, yaw, sx, sy, sz)."""
    lines = []
    if start is not None:
        lines.append("start: [%g, %g, %g]" % tuple(start))
    if boxes:
        lines.append("boxes:")
        lines += ["  - {pose: [%g, %g, %g], size: [%g, %g, %g]}" % tuple(b) for b in boxes]
    if cylinders:
        lines.append("cylinders:")
        lines += ["  - {position: [%g, %g], radius: %g, height: %g}" % tuple(c) for c in cylinders]
    path = Path(directory) / f"{name}.yaml"
    path.write_text("\n".join(lines) + "\n" + extra)
    return path


def wall_ahead(directory, face_x, thickness=1.0, name="wall"):
    """A 10 m long, 1 m high wall whose near face is at x = face_x."""
    return write_world(directory, name, boxes=[(face_x + thickness / 2, 0, 0, thickness, 10, 1)])


def start_simulator(ros, world, speed=5.0, noise=False, **params):
    """rosrun the simulator with private params (sim time on) and wait for its /clock."""
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    args = [f"_world:={world}", f"_speed:={speed}"]
    if not noise:
        args += ["_odom_noise:=false", "_sensor_noise:=false"]
    args += [f"_{k}:={v}" for k, v in params.items()]
    proc = ros.start(["rosrun", "bullet_turtlebot", "simulator", *args], name="simulator")
    ros.wait_for_topic("/clock")
    return proc


def drive(ros, linear, angular, seconds, topic="cmd_vel_mux/input/teleop", rate=10.0, stop=True):
    """Publish a Twist at `rate` Hz of sim time for `seconds` of sim time (then zero)."""
    cmd = [DEBIAN_PYTHON, str(DRIVE), f"--topic={topic}", f"--linear={linear}"]
    cmd += [f"--angular={angular}", f"--seconds={seconds}", f"--rate={rate}"]
    if not stop:
        cmd.append("--no-stop")
    return ros.run(cmd, timeout=120)


def publish_once(ros, topic, linear=0.0, angular=0.0, count=3):
    """Publish a few raw Twist messages (values may be nan/inf) on topic."""
    cmd = [DEBIAN_PYTHON, str(DRIVE), f"--topic={topic}", f"--linear={linear}"]
    cmd += [f"--angular={angular}", f"--count={count}", "--no-stop"]
    return ros.run(cmd, timeout=60)


def last_pose(ros, topic="base_pose_ground_truth"):
    msg = ros.echo(topic, count=1)[0]["msg"]
    p = msg["pose"]["pose"]
    return p["position"]["x"], p["position"]["y"], yaw_of(p["orientation"]), msg


def secs(value):
    """A probe-recorded time: a float, or {"secs", "nsecs"} for some message types."""
    if isinstance(value, dict):
        return value["secs"] + value["nsecs"] * 1e-9
    return value


def sim_time(ros):
    return ros.sim_time()


def wait_sim_seconds(ros, seconds, timeout=60):
    """Block until the simulator's clock has advanced by `seconds`."""
    t0 = sim_time(ros)
    ros.wait_for(lambda: sim_time(ros) >= t0 + seconds, timeout, f"{seconds} s of sim time")


def call_service(ros, name, srv_type="std_srvs/Empty"):
    return ros.run(["rosservice", "call", name])


def ranges(msg):
    """LaserScan ranges from a probe record (inf/nan arrive as strings)."""
    return [float(r) for r in msg["ranges"]]


def exited(proc, timeout=20):
    try:
        return proc.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
