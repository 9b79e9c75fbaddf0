"""Keep a rospy node in the graph when roscore is killed and started again.

ROS 1 nodes outlive their master, but rospy registers its publishers, subscribers and
services only once, at start-up: a new master knows none of them, so `rostopic echo`,
`rosnode list`, service calls and nodes started later find nothing (the connections made
before the restart go on working, peer to peer).

Nodes call `survive_master_restart()` once, after `rospy.init_node()`. A daemon thread asks
the master for its pid and `/run_id` once a wall second (two small XML-RPC calls); when
they change (a new master; the same one answering late, or getting its `/run_id` a moment
after it first answered, changes nothing: see `same_master`), it registers every
publisher, subscriber and service of the node again, with the node's own XML-RPC URI, tells
the node's subscribers about the publishers the new master already knows, and puts back the
node's private parameters (as they were when the watch started) and, if the node publishes
`/clock`, `/use_sim_time`. Nothing else changes while the master stays the same.
"""

import http.client
import threading
import xmlrpc.client

import rosgraph
import rospy
import rospy.core
import rospy.impl.registration
import rospy.rostime

POLL = 1.0  # wall seconds between checks: "within a few seconds" at no measurable cost
TIMEOUT = 2.0  # wall seconds for one XML-RPC call, so a stopped master cannot block the watch


class _TimeoutTransport(xmlrpc.client.Transport):
    def make_connection(self, host):
        connection = super().make_connection(host)
        connection.timeout = TIMEOUT
        return connection


def timed_proxy(uri):
    """An XML-RPC proxy whose calls give up after TIMEOUT s (rosgraph's wait forever)."""
    return xmlrpc.client.ServerProxy(uri, transport=_TimeoutTransport(), allow_none=True)


def survive_master_restart(poll=POLL):
    """Start the watch (a daemon thread) and return it; None if the node has no master."""
    node_uri = rospy.core.get_node_uri()
    master_uri = rosgraph.get_master_uri()
    if not node_uri or not master_uri:
        return None
    watch = _MasterWatch(master_uri, node_uri)
    watch.snapshot_private_params()
    stop = threading.Event()
    rospy.core.add_preshutdown_hook(lambda _reason: stop.set())
    thread = threading.Thread(target=watch.run, args=(poll, stop), name="master_watch", daemon=True)
    thread.start()
    return thread


def same_master(known, seen):
    """Whether the master that answers now, `seen` (pid, run_id), is `known`, the one the node
    registered with. roscore's roslaunch sets /run_id after its rosmaster answers (it checks
    for the master every 0.1 s, then sets it), so a watch that registered in between knows
    that master's pid with no run_id yet: the run_id arriving later is the same master, not
    a second restart. (A new master with the very same pid is told apart by its run_id.)"""
    if known is None or seen is None:
        return known == seen
    return seen == known or (seen[0] == known[0] and known[1] == "")


class _MasterWatch:
    def __init__(self, master_uri, node_uri):
        self.master_uri = master_uri
        self.node_uri = node_uri
        self.caller_id = rospy.get_caller_id()
        self.private_ns = self.caller_id  # getParam of a namespace gives its whole tree
        self.private_params = None
        self.identity = self.master_identity()

    def master_identity(self):
        """(pid, run_id) of the master, or None when it does not answer."""
        try:
            master = timed_proxy(self.master_uri)
            code, _, pid = master.getPid(self.caller_id)
            if code != 1:
                return None
            code, _, run_id = master.getParam(self.caller_id, "/run_id")
            return pid, (run_id if code == 1 else "")
        except (OSError, http.client.HTTPException, xmlrpc.client.Error):
            return None

    def snapshot_private_params(self):
        try:
            code, _, value = timed_proxy(self.master_uri).getParam(self.caller_id, self.private_ns)
            if code == 1 and isinstance(value, dict) and value:
                self.private_params = value
        except (OSError, http.client.HTTPException, xmlrpc.client.Error):
            pass  # nothing to put back later

    def run(self, poll, stop):
        warned = False
        # Waiting on wall time: the master's presence is what is polled, not ROS time.
        while not stop.wait(poll) and not rospy.core.is_shutdown_requested():
            try:
                identity = self.master_identity()
                # Only a new master (its pid and run_id) is acted on: the same master slow to
                # answer (a loaded machine) or unreachable for a while still knows the node.
                if identity is None:
                    continue
                if same_master(self.identity, identity):
                    self.identity = identity  # with the run_id roslaunch has set since
                    continue
                self.register_all()
                self.identity, warned = identity, False
            except Exception as err:  # the watch must never take the node down
                if not warned:
                    rospy.logwarn(
                        "master_watch: cannot register with the new master at %s yet (%s); "
                        "trying again every %g s",
                        self.master_uri,
                        err,
                        poll,
                    )
                    warned = True

    def register_all(self):
        topics = rospy.impl.registration.get_topic_manager()
        services = rospy.impl.registration.get_service_manager()
        pubs, subs = [], []
        if topics is not None:
            with topics.lock:  # as rospy's RegManager does: no change while the lists are read
                pubs, subs = topics.get_publications(), topics.get_subscriptions()
        srvs = services.get_services() if services else []
        master = timed_proxy(self.master_uri)
        node = timed_proxy(self.node_uri)
        for name, data_type in pubs:
            if rospy.core.is_shutdown_requested():
                return
            master.registerPublisher(self.caller_id, name, data_type, self.node_uri)
        for name, data_type in subs:
            if rospy.core.is_shutdown_requested():
                return
            code, _, publishers = master.registerSubscriber(
                self.caller_id, name, data_type, self.node_uri
            )
            if code == 1 and publishers:
                # What the master does for subscribers it knows when a publisher registers.
                # rospy only adds connections on an update, so live ones are kept.
                node.publisherUpdate("/master", name, publishers)
        for name, service_uri in srvs:
            if rospy.core.is_shutdown_requested():
                return
            master.registerService(self.caller_id, name, service_uri, self.node_uri)
        restored = self.restore_params(master, publishes_clock=any(n == "/clock" for n, _ in pubs))
        rospy.loginfo(
            "master_watch: new master at %s: registered %d publishers, %d subscribers, "
            "%d services again%s",
            self.master_uri,
            len(pubs),
            len(subs),
            len(srvs),
            "; restored " + ", ".join(restored) if restored else "",
        )

    def restore_params(self, master, publishes_clock):
        """Put back what a launch had set for this node, only where the new master has nothing:
        its private parameters, and /use_sim_time if the node is the clock (a node that only
        runs on sim time does not: it may be the one waiting for a /clock that is gone)."""
        restored = []
        if self.private_params is not None:
            code, _, present = master.hasParam(self.caller_id, self.private_ns)
            if code == 1 and not present:
                master.setParam(self.caller_id, self.private_ns, self.private_params)
                restored.append(self.private_ns)
        if publishes_clock and not rospy.rostime.is_wallclock():
            code, _, present = master.hasParam(self.caller_id, "/use_sim_time")
            if code == 1 and not present:
                master.setParam(self.caller_id, "/use_sim_time", True)
                restored.append("/use_sim_time")
        return restored
