"""`master`: asks the test's roscore directly over XML-RPC (no CLI process per poll), so
waiting for topics, services and nodes costs almost no CPU on a loaded machine."""

import xmlrpc.client

import pytest
from roskit import RosGraph

CALLER = "/basics_tests"


class Master:
    def __init__(self, ros):
        self.ros = ros
        self.uri = ros.env["ROS_MASTER_URI"]

    def _state(self):
        code, message, state = xmlrpc.client.ServerProxy(self.uri).getSystemState(CALLER)
        if code != 1:
            raise RuntimeError(f"getSystemState: {message}")
        return state  # publishers, subscribers, services: [[name, [node, ...]], ...]

    def publishers(self, topic):
        return set(dict(self._state()[0]).get(_absolute(topic), []))

    def subscribers(self, topic):
        return set(dict(self._state()[1]).get(_absolute(topic), []))

    def topics(self):
        publishers, subscribers, _ = self._state()
        return {name for name, _ in publishers + subscribers}

    def services(self):
        return {name for name, _ in self._state()[2]}

    def nodes(self):
        return {node for group in self._state() for _, nodes in group for node in nodes}

    def wait_for_topic(self, topic, timeout=60):
        self.ros.wait_for(lambda: self.publishers(topic), timeout, f"a publisher of {topic}")

    def wait_for_service(self, service, timeout=60):
        name = _absolute(service)
        self.ros.wait_for(lambda: name in self.services(), timeout, f"service {name}")


def _absolute(name):
    return "/" + name.lstrip("/")


@pytest.fixture
def master(ros):
    return Master(ros)


@pytest.fixture(scope="module")
def shared_graph(tmp_path_factory, request):
    """One roscore for a whole test module (saves a roscore start-up per test). The module
    names the nodes to start in SHARED_NODES and what to wait for in SHARED_TOPICS and
    SHARED_SERVICES."""
    module = request.module
    graph = RosGraph(tmp_path_factory.mktemp(module.__name__.rsplit(".", 1)[-1]))
    try:
        for cmd in module.SHARED_NODES:
            graph.start(cmd)
        master = Master(graph)
        for topic in getattr(module, "SHARED_TOPICS", ()):
            master.wait_for_topic(topic)
        for service in getattr(module, "SHARED_SERVICES", ()):
            master.wait_for_service(service)
        yield graph
    finally:
        graph.close()
