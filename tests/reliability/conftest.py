"""One roscore for a whole module of reliability rows: each row is a node refusing its
parameters at start-up, so a fresh master per row would only add start-up time."""

import pytest
from roskit import RosGraph


@pytest.fixture(scope="module")
def shared_ros(tmp_path_factory, request):
    ros = RosGraph(tmp_path_factory.mktemp(request.module.__name__.rsplit(".", 1)[-1]))
    try:
        yield ros
    finally:
        ros.close()
