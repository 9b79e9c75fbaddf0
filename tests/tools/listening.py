"""The TCP ports a process listens on and the UDP ports it has bound, from /proc (Linux)."""

import os
from pathlib import Path


def _socket_inodes(pid):
    inodes = set()
    fd_dir = Path(f"/proc/{pid}/fd")
    for fd in os.listdir(fd_dir):
        try:
            target = os.readlink(fd_dir / fd)
        except OSError:
            continue  # closed meanwhile
        if target.startswith("socket:["):
            inodes.add(target[len("socket:[") : -1])
    return inodes


def _ports(pid, tables, state=None):
    inodes = _socket_inodes(pid)
    ports = set()
    for table in tables:
        path = Path(f"/proc/{pid}/net/{table}")
        if not path.exists():
            continue
        for line in path.read_text().splitlines()[1:]:
            fields = line.split()
            local, st, inode = fields[1], fields[3], fields[9]
            if inode in inodes and (state is None or st == state):
                ports.add(int(local.rsplit(":", 1)[1], 16))
    return ports


def tcp_listening_ports(pid):
    return _ports(pid, ("tcp", "tcp6"), state="0A")  # 0A: LISTEN


def udp_ports(pid):
    return _ports(pid, ("udp", "udp6"))
