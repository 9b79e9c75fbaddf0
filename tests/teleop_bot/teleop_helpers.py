"""Shared bits of the teleop_bot integration tests."""

from pathlib import Path

HERE = Path(__file__).resolve().parent
SEND_KEYS = ["/usr/bin/python3", str(HERE / "send_keys.py")]


def twists(messages):
    """(ros time, linear x, angular z) per recorded Twist."""
    return [(m["ros"], m["msg"]["linear"]["x"], m["msg"]["angular"]["z"]) for m in messages]


def rate_hz(times):
    if len(times) < 2 or times[-1] <= times[0]:
        return 0.0
    return (len(times) - 1) / (times[-1] - times[0])


def values_between(samples, start, end):
    return [(lin, ang) for t, lin, ang in samples if start <= t < end]


def start_in_terminal(ros, cmd, name):
    """Start `cmd` with a fresh pseudo-terminal as its controlling terminal and stdin (as if
    typed in a terminal window); returns (proc, master fd, slave fd). Output goes to the
    graph's log file. Writing b"\\x03" to the master is a real Ctrl-C."""
    import fcntl
    import os
    import subprocess
    import termios

    master, slave = os.openpty()
    ros._log_index += 1
    log_path = ros.workdir / f"{ros._log_index:02d}-{name}.log"
    log = open(log_path, "w")

    def take_terminal():
        fcntl.ioctl(0, termios.TIOCSCTTY, 0)

    proc = subprocess.Popen(
        cmd,
        stdin=slave,
        stdout=log,
        stderr=subprocess.STDOUT,
        env=ros.env,
        cwd=ros.workdir,
        start_new_session=True,
        preexec_fn=take_terminal,
    )
    proc.log_path, proc.label = log_path, name
    ros.procs.append(proc)
    return proc, master, slave
