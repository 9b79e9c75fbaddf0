"""The ROS computation graph as Graphviz DOT, drawn the way rqt_graph draws it: nodes are
ellipses, topics are boxes, publishers point at their topics and topics at subscribers."""

from dataclasses import dataclass, field

DEBUG_TOPICS = {"/rosout", "/rosout_agg"}
DEBUG_NODES = {"/rosout"}


@dataclass
class RosGraph:
    nodes: list = field(default_factory=list)
    topics: list = field(default_factory=list)
    publications: list = field(default_factory=list)  # (node, topic)
    subscriptions: list = field(default_factory=list)  # (topic, node)

    def edges(self):
        return self.publications + self.subscriptions


def build_graph(publishers, subscribers, hide_debug=True, hide_leaf_topics=True, exclude=()):
    """From the master's system state lists `[[topic, [node, ...]], ...]`.

    hide_debug drops rosout; hide_leaf_topics keeps only topics with a publisher and a
    subscriber (rqt_graph's default view); `exclude` names nodes to leave out (the tool's own).
    """
    skip_nodes = set(exclude) | (DEBUG_NODES if hide_debug else set())
    pubs = {t: set(ns) - skip_nodes for t, ns in publishers}
    subs = {t: set(ns) - skip_nodes for t, ns in subscribers}
    topics = {t for t in set(pubs) | set(subs) if pubs.get(t) or subs.get(t)}
    if hide_debug:
        topics -= DEBUG_TOPICS
    if hide_leaf_topics:
        topics = {t for t in topics if pubs.get(t) and subs.get(t)}
    publications = sorted((n, t) for t in topics for n in pubs.get(t, ()))
    subscriptions = sorted((t, n) for t in topics for n in subs.get(t, ()))
    nodes = {n for n, _ in publications} | {n for _, n in subscriptions}
    return RosGraph(sorted(nodes), sorted(topics), publications, subscriptions)


def _quote(name):
    return '"' + name.replace("\\", "\\\\").replace('"', '\\"') + '"'


def to_dot(graph):
    """DOT text; ids carry a prefix so a node and a topic of the same name stay apart."""

    def node_id(name):
        return _quote("n" + name)

    def topic_id(name):
        return _quote("t" + name)

    lines = ["digraph rosgraph {", "  rankdir=LR;", '  node [fontname="Helvetica"];']
    lines += [f"  {node_id(n)} [label={_quote(n)}, shape=ellipse];" for n in graph.nodes]
    lines += [f"  {topic_id(t)} [label={_quote(t)}, shape=box];" for t in graph.topics]
    lines += [f"  {node_id(n)} -> {topic_id(t)};" for n, t in graph.publications]
    lines += [f"  {topic_id(t)} -> {node_id(n)};" for t, n in graph.subscriptions]
    lines.append("}")
    return "\n".join(lines) + "\n"
