"""Helpers for tests that drive the bullet_turtlebot simulator: start it, record by sim time,
ground-truth motion and bumper contact figures."""

import math
import os
import subprocess
import time

import pytest
from rosbook_env.geometry import yaw_of

# Sim speed for the tests (1.0 = real time). Faster than real time, yet slow enough that
# 10 Hz Python nodes keep up on a loaded 2-core machine (the base stops 0.6 s sim time
# after its last command, so a lagging node would make the robot stutter).
SIM_SPEED = float(os.environ.get("ROSBOOK_SIM_SPEED", "2"))


def require_simulator():
    done = subprocess.run(["rospack", "find", "bullet_turtlebot"], capture_output=True)
    if done.returncode != 0:
        pytest.skip("bullet_turtlebot is not in this workspace")


def start_sim(ros, launch="simulator.launch", pkg="bullet_turtlebot", **args):
    """roslaunch the simulator paused (start_paused:=true); call unpause() when ready."""
    require_simulator()
    argv = [f"{k}:={v}" for k, v in args.items()]
    proc = ros.start(["roslaunch", pkg, launch, "start_paused:=true", *argv], name="sim")
    ros.wait_for_service("simulator/unpause", timeout=60)
    return proc


def unpause(ros):
    ros.run(["rosservice", "call", "/simulator/unpause"])


def wait_sim_seconds(ros, probe, sim_seconds, topic, timeout=600):
    """Block until the probe has seen `topic` messages spanning `sim_seconds` of sim time."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        stamps = [m["ros"] for m in probe.messages() if m["topic"] == topic]
        if stamps and stamps[-1] - stamps[0] >= sim_seconds:
            return
        if probe.proc.poll() is not None:
            break
        time.sleep(0.5)
    raise AssertionError(f"{sim_seconds} s of sim time did not pass on {topic}")


def poses(messages, topic="base_pose_ground_truth"):
    """(sim time, x, y, yaw) per ground-truth Odometry message."""
    out = []
    for m in messages:
        if m["topic"] != topic:
            continue
        p = m["msg"]["pose"]["pose"]
        out.append((m["ros"], p["position"]["x"], p["position"]["y"], yaw_of(p["orientation"])))
    return out


def path_length(samples):
    return sum(
        math.hypot(b[1] - a[1], b[2] - a[2]) for a, b in zip(samples, samples[1:], strict=False)
    )


def contact_time(messages, start, end, topic="mobile_base/events/bumper"):
    """Sim seconds within [start, end] during which any bumper was pressed."""
    pressed = set()
    since = None
    total = 0.0
    for m in sorted((m for m in messages if m["topic"] == topic), key=lambda m: m["ros"]):
        t = min(max(m["ros"], start), end)
        was = bool(pressed)
        if m["msg"]["state"] == 1:
            pressed.add(m["msg"]["bumper"])
        else:
            pressed.discard(m["msg"]["bumper"])
        if not was and pressed:
            since = t
        elif was and not pressed:
            total += t - since
    if pressed and since is not None:
        total += end - since
    return total


def write_room(directory, width=6.0, height=4.0, start=(1.0, 2.0, 0.0), resolution=0.05):
    """A walled empty room as a world YAML + PGM; returns (yaml path, inner wall faces)."""
    cols, rows = round(width / resolution), round(height / resolution)
    wall = 3  # cells (0.15 m)
    pixels = bytearray([254]) * (cols * rows)
    for r in range(rows):
        for c in range(cols):
            if r < wall or r >= rows - wall or c < wall or c >= cols - wall:
                pixels[r * cols + c] = 0
    (directory / "room.pgm").write_bytes(b"P5\n%d %d\n255\n" % (cols, rows) + bytes(pixels))
    yaml = directory / "room.yaml"
    yaml.write_text(
        "image: room.pgm\n"
        f"resolution: {resolution}\n"
        "origin: [0, 0, 0]\n"
        "negate: 0\n"
        "occupied_thresh: 0.65\n"
        "free_thresh: 0.196\n"
        "wall_height: 1.0\n"
        f"start: [{start[0]}, {start[1]}, {start[2]}]\n"
    )
    inner = wall * resolution
    return yaml, {"xmin": inner, "xmax": width - inner, "ymin": inner, "ymax": height - inner}
