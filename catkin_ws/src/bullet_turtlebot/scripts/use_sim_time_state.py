#!/usr/bin/python3
"""Print /use_sim_time as the master holds it now: true, false, other or unset.

simulator.launch runs this from a `<param command=...>`, which roslaunch evaluates while it
reads the file, before it sets any parameter (and before it starts a master of its own):
so the output is the value from before the launch, which the simulator puts back when it
exits cleanly. No master (roslaunch is about to start one) means unset. Never fails, so
the launch never fails because of it.
"""

import os
import socket
import sys
import xmlrpc.client


def state(master_uri, timeout=3.0):
    socket.setdefaulttimeout(timeout)
    try:
        code, _, value = xmlrpc.client.ServerProxy(master_uri).getParam(
            "/use_sim_time_state", "/use_sim_time"
        )
    except (OSError, xmlrpc.client.Error):
        return "unset"
    if code != 1:
        return "unset"
    if value is True or value is False:
        return str(value).lower()
    return "other"


if __name__ == "__main__":
    sys.stdout.write(state(os.environ.get("ROS_MASTER_URI", "http://localhost:11311")))
