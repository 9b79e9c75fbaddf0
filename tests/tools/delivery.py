"""Has a subscriber taken in what we published? Counted from both ends of each connection.

Writing a message to a subscriber's socket (a synchronous rospy publisher) does not mean the
node has read it: under load the node's receive thread can fall behind, and a subscriber
with queue_size=1 that then reads several messages at once keeps only the newest. Tests that
inject one input per tick wait until each subscriber's own count of messages received from
us (the node's getBusStats over its XML-RPC API, which rospy and roscpp both serve) reaches
the count our publisher wrote to it. rospy counts a message when its receive thread has read
it, just before it runs the callback in that same thread.
"""

import xmlrpc.client

import rosgraph
import rospy
from rosbook_env.master_watch import timed_proxy


def a_publisher_sends_to_us(sub):
    """Whether a publisher of `sub`'s topic has us in its own list of connections (as its
    node's getBusInfo says). Our side counts a connection once the publisher's header arrives,
    which rospy's publisher sends before it adds the connection to those it publishes to: a
    message published in between is lost (a Twist answering a test's first key was).
    Publishers that do not answer (a killed node's registration) are passed over."""
    if sub.get_num_connections() == 0:
        return False
    me = rospy.get_name()
    master = rosgraph.Master(me)
    for topic, nodes in master.getSystemState()[0]:
        if topic != sub.name:
            continue
        for node in nodes:
            try:
                code, _, info = timed_proxy(master.lookupNode(node)).getBusInfo(me)
            except (OSError, xmlrpc.client.Error, rosgraph.MasterError):
                continue
            if code == 1 and any(
                row[1] == me and row[2] == "o" and row[4] == sub.name for row in info
            ):
                return True
    return False


class Delivery:
    """Counts, per subscriber of `pub`, messages written (here) and received (there)."""

    def __init__(self, pub):
        self.pub = pub
        self.topic = pub.resolved_name
        self.me = rospy.get_name()
        self.my_uri = rospy.get_node_uri()
        self.master = rosgraph.Master(self.me)
        self.proxies = {}  # subscriber node name -> its XML-RPC API
        self.confirmed = {}  # subscriber node name -> messages known to have been read

    def written(self):
        """{subscriber node: messages our publisher has written to it}"""
        return {c.endpoint_id: c.stat_num_msg for c in list(self.pub.impl.connections)}

    def received(self, node):
        """Messages `node` has read from our connection on the topic (0 if none yet)."""
        if node not in self.proxies:
            self.proxies[node] = timed_proxy(self.master.lookupNode(node))
        proxy = self.proxies[node]
        try:
            code, _, info = proxy.getBusInfo(self.me)
            if code == 1:
                code, _, stats = proxy.getBusStats(self.me)
        except (OSError, xmlrpc.client.Error):
            return 0  # a node too busy to answer within the timeout: asked again next time
        if code != 1:
            return 0
        # (connection id, publisher's URI, direction, transport, topic, ...)
        from_me = {c[0] for c in info if c[4] == self.topic and c[1] == self.my_uri}
        for topic, connections in stats[1]:  # subscriptions: (id, bytes, messages, ...)
            if topic == self.topic:
                return sum(c[2] for c in connections if c[0] in from_me)
        return 0

    def taken(self):
        """True once every subscriber has read every message we wrote to it."""
        for node, sent in self.written().items():
            if self.confirmed.get(node, -1) < sent:
                self.confirmed[node] = self.received(node)
                if self.confirmed[node] < sent:
                    return False
        return True
