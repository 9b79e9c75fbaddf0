"""The test kit's own guarantees, with a real rosmaster."""

import socket

import roskit


def test_a_master_whose_port_was_taken_is_started_again_on_another(tmp_path, monkeypatch):
    """A free port can be taken before rosmaster binds it; rosmaster then stays up without
    serving, and the graph must not wait on it for a minute and fail."""
    with socket.socket() as holder:
        holder.bind(("127.0.0.1", 0))
        holder.listen()
        taken = holder.getsockname()[1]
        ports = iter([taken])
        real_free_port = roskit.free_port
        monkeypatch.setattr(roskit, "free_port", lambda: next(ports, None) or real_free_port())
        graph = roskit.RosGraph(tmp_path)
        try:
            assert graph.port != taken
            assert graph.master().getPid("/test_roskit")[0] == 1
            assert graph.env["ROS_MASTER_URI"].endswith(f":{graph.port}")
        finally:
            graph.close()
