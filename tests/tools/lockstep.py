"""Test-side helpers for lockstep_clock.py: start it against a RosGraph, read its records."""

import json
import subprocess
from pathlib import Path

HERE = Path(__file__).resolve().parent
SCRIPT = HERE / "lockstep_clock.py"
PYTHON = "/usr/bin/python3"
# A message arrives at the tick of its deadline or up to this many ticks later (rospy.Rate's
# start-up messages still on their way; see lockstep_clock.py).
SLACK_TICKS = 2


def start(ros, gate, period, ticks, *options, pass_fds=(), name="lockstep_clock"):
    """Start lockstep_clock.py (it waits for the node); returns the process, with .out."""
    args = ["--gate", gate, "--period", period, "--ticks", ticks, *options]
    return launch(ros, [PYTHON, str(SCRIPT), *map(str, args)], name, pass_fds)


def launch(ros, cmd, name, pass_fds=()):
    """Start a lock-step clock script `cmd` (given --out here) against the graph `ros`."""
    ros._log_index += 1
    index = ros._log_index
    out = ros.workdir / f"{index:02d}-{name}.jsonl"
    log_path = ros.workdir / f"{index:02d}-{name}.log"
    proc = subprocess.Popen(
        [*cmd, "--out", str(out)],
        stdout=open(log_path, "w"),
        stderr=subprocess.STDOUT,
        stdin=subprocess.DEVNULL,
        env=ros.env,
        cwd=ros.workdir,
        start_new_session=True,
        pass_fds=pass_fds,
    )
    proc.log_path, proc.label, proc.out = log_path, name, out
    ros.procs.append(proc)
    return proc


def finish(ros, proc, timeout=300):
    """Wait for the clock's last tick; returns its records [{"tick", "clock", "msg"}]."""
    try:
        code = proc.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        ros.stop(proc)
        code = "still running"
    if code != 0:
        raise AssertionError(f"lockstep clock failed ({code}):\n" + ros.output(proc))
    return records(proc)


def records(proc):
    if not Path(proc.out).exists():
        return []
    lines = Path(proc.out).read_text().splitlines()
    return [r for r in map(json.loads, filter(None, lines)) if "msg" in r]
