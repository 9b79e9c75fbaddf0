"""A SimpleActionClient without the start-of-goal race of Debian's actionlib 1.14.

SimpleActionClient.send_goal stores the goal handle only after the goal is on the wire,
and its callbacks drop whatever arrives before that: a server that answers at once loses
its first feedback (the fancy timer's "Time elapsed: 0.000"), or even the DONE transition
of an immediate abort, and wait_for_result() then hangs. Here the callbacks wait until
send_goal has stored the handle.
"""

import threading

import actionlib


class SimpleActionClient(actionlib.SimpleActionClient):
    def __init__(self, ns, action_spec):
        self._sending = threading.RLock()  # reentrant: a callback may run inside send_goal
        super().__init__(ns, action_spec)

    def send_goal(self, goal, done_cb=None, active_cb=None, feedback_cb=None):
        with self._sending:
            super().send_goal(goal, done_cb, active_cb, feedback_cb)

    def _handle_transition(self, gh):
        with self._sending:
            pass
        super()._handle_transition(gh)

    def _handle_feedback(self, gh, feedback):
        with self._sending:
            pass
        super()._handle_feedback(gh, feedback)
