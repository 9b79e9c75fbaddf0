"""Building the node/topic graph and its DOT text."""

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from rqt_lite.graph import build_graph, to_dot  # noqa: E402

PUBS = [
    ["/chatter", ["/talker"]],
    ["/rosout", ["/talker", "/listener"]],
    ["/rosout_agg", ["/rosout"]],
    ["/lonely", ["/talker"]],
]
SUBS = [["/chatter", ["/listener", "/other"]], ["/rosout", ["/rosout"]]]


def test_default_view_is_talker_chatter_listener():
    g = build_graph(PUBS, SUBS)
    assert g.nodes == ["/listener", "/other", "/talker"]
    assert g.topics == ["/chatter"]
    assert g.publications == [("/talker", "/chatter")]
    assert g.subscriptions == [("/chatter", "/listener"), ("/chatter", "/other")]


def test_all_shows_debug_and_leaf_topics():
    g = build_graph(PUBS, SUBS, hide_debug=False, hide_leaf_topics=False)
    assert set(g.topics) == {"/chatter", "/rosout", "/rosout_agg", "/lonely"}
    assert "/rosout" in g.nodes
    assert ("/talker", "/lonely") in g.publications


def test_exclude_drops_a_node_and_its_lonely_topics():
    g = build_graph([["/a", ["/probe"]]], [["/a", ["/x"]]], exclude=["/probe"])
    assert g.topics == [] and g.nodes == []


def test_dot_shapes_and_edges():
    dot = to_dot(build_graph(PUBS, SUBS))
    assert '"n/talker" [label="/talker", shape=ellipse];' in dot
    assert '"t/chatter" [label="/chatter", shape=box];' in dot
    assert '"n/talker" -> "t/chatter";' in dot
    assert '"t/chatter" -> "n/listener";' in dot


def test_a_node_and_a_topic_may_share_a_name():
    dot = to_dot(build_graph([["/x", ["/x"]]], [["/x", ["/y"]]]))
    assert '"n/x" -> "t/x";' in dot and '"t/x" -> "n/y";' in dot


@pytest.mark.skipif(shutil.which("dot") is None, reason="graphviz not installed")
def test_graphviz_accepts_the_dot():
    dot = to_dot(build_graph(PUBS, SUBS))
    done = subprocess.run(["dot", "-Tsvg"], input=dot.encode(), capture_output=True)
    assert done.returncode == 0, done.stderr
    assert b"/chatter" in done.stdout
