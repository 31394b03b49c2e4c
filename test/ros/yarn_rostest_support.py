"""Helpers shared by the yarn_tearing rostest nodes (imported from the test scripts' folder)."""
import math
import threading
import time

import rospy
import yaml
from yarn_tearing.msg import BreakEvent, YarnStateArray


def load_yaml(path):
    with open(path) as stream:
        return yaml.safe_load(stream)


def wait_until(predicate, timeout, period=0.02):
    """Polls `predicate` until it is true or `timeout` wall seconds passed; returns its value."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline and not rospy.is_shutdown():
        value = predicate()
        if value:
            return value
        time.sleep(period)
    return predicate()


def find_yarn(states, name):
    for yarn in states.yarns:
        if yarn.name == name:
            return yarn
    raise KeyError("no yarn %r in yarn_states" % name)


def vector_norm(v):
    return math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z)


def state_is_finite(states):
    """True when every number of every yarn in a YarnStateArray is finite."""
    for yarn in states.yarns:
        for p in list(yarn.positions) + list(yarn.velocities) + list(yarn.support_forces):
            if not all(math.isfinite(c) for c in (p.x, p.y, p.z)):
                return False
        for values in (yarn.rest_lengths, yarn.tensions, yarn.stresses, yarn.strains,
                       yarn.plastic_strains, yarn.strain_limits):
            if not all(math.isfinite(x) for x in values):
                return False
    return True


class StateRecorder:
    """Records yarn_states with their wall receive time [s, time.monotonic()]."""

    def __init__(self, topic="yarn_states"):
        self._lock = threading.Lock()
        self._records = []
        self._subscriber = rospy.Subscriber(topic, YarnStateArray, self._on_state, queue_size=100)

    def _on_state(self, msg):
        with self._lock:
            self._records.append((time.monotonic(), msg))

    def records(self, since=float("-inf")):
        with self._lock:
            return [(t, m) for t, m in self._records if t >= since]

    def latest(self):
        with self._lock:
            return self._records[-1][1] if self._records else None

    def wait_for_states(self, timeout=15.0):
        return wait_until(lambda: self.latest() is not None, timeout)


class BreakRecorder:
    """Records break_events."""

    def __init__(self, topic="break_events"):
        self._lock = threading.Lock()
        self._events = []
        self._subscriber = rospy.Subscriber(topic, BreakEvent, self._on_break, queue_size=1000)

    def _on_break(self, msg):
        with self._lock:
            self._events.append(msg)

    def events(self):
        with self._lock:
            return list(self._events)


def measured_rate(records):
    """Messages per wall second over a list of (receive time, msg)."""
    if len(records) < 2:
        return 0.0
    return (len(records) - 1) / (records[-1][0] - records[0][0])
