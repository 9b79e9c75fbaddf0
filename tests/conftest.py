"""Shared fixtures: `ros` gives each test its own roscore on a free port."""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from roskit import RosGraph  # noqa: E402


@pytest.fixture
def ros(tmp_path):
    graph = RosGraph(tmp_path)
    try:
        yield graph
    finally:
        graph.close()
