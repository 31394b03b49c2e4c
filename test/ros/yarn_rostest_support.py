"""Helpers shared by the yarn_tearing rostest nodes (imported from the test scripts' folder)."""
import concurrent.futures
import math
import os
import subprocess
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


def run_under_names(binary, names, timeout):
    """Runs `binary __name:=<name>` once for each of `names` and returns their CompletedProcess
    (stdout and stderr captured as text), in the order of `names`. Four run per core at a time: a
    node or check_config that refuses its parameters spends most of its run in roscpp's start
    and shutdown, waiting on the master and on threads that poll every 0.1 s (0.3 s wall for
    0.02 s of processor time), and check_config bounds its stepping in processor time."""
    def run(name):
        return subprocess.run([binary, "__name:=" + name], capture_output=True, text=True,
                              timeout=timeout)

    workers = 4 * (os.cpu_count() or 1)
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        return list(pool.map(run, names))


def find_yarn(states, name):
    for yarn in states.yarns:
        if yarn.name == name:
            return yarn
    raise KeyError("no yarn %r in yarn_states" % name)


def vector_norm(v):
    return math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z)


def parts_are_finite(parts, vector_fields, number_fields):
    """True when every vector of `vector_fields` and every number of `number_fields` of each of
    `parts` (the yarns of a YarnStateArray, the fabrics of a FabricStateArray) is finite."""
    for part in parts:
        for name in vector_fields:
            for p in getattr(part, name):
                if not all(math.isfinite(c) for c in (p.x, p.y, p.z)):
                    return False
        for name in number_fields:
            if not all(math.isfinite(x) for x in getattr(part, name)):
                return False
    return True


def state_is_finite(states):
    """True when every number of every yarn in a YarnStateArray is finite."""
    return parts_are_finite(states.yarns, ("positions", "velocities", "support_forces"),
                            ("rest_lengths", "tensions", "stresses", "strains", "plastic_strains",
                             "strain_limits"))


def fabric_state_is_finite(states):
    """True when every number of every fabric in a FabricStateArray is finite."""
    return parts_are_finite(states.fabrics, ("positions", "velocities", "support_forces"),
                            ("rest_lengths", "tensions", "stresses", "strains", "plastic_strains"))


class TopicRecorder:
    """Records every message of one topic with its wall receive time [s, time.monotonic()]."""

    def __init__(self, topic, message_type):
        self._lock = threading.Lock()
        self._records = []
        self._subscriber = rospy.Subscriber(topic, message_type, self._on_message, queue_size=10000)

    def _on_message(self, msg):
        with self._lock:
            self._records.append((time.monotonic(), msg))

    def records(self, since=float("-inf")):
        """(receive time, msg) pairs received at or after `since`."""
        with self._lock:
            return [(t, m) for t, m in self._records if t >= since]

    def messages(self):
        with self._lock:
            return [m for _, m in self._records]

    def latest(self):
        with self._lock:
            return self._records[-1][1] if self._records else None

    def wait_for_first(self, timeout=15.0):
        return wait_until(lambda: self.latest() is not None, timeout)


def record_states(topic="yarn_states"):
    """Records yarn_states."""
    return TopicRecorder(topic, YarnStateArray)


def record_breaks(topic="break_events"):
    """Records break_events."""
    return TopicRecorder(topic, BreakEvent)


def start_client(test_class, node_name):
    """Starts a test node and gives `test_class` the node's config (~config), its first yarn and a
    yarn_states recorder; fails unless states arrive within 15 s."""
    rospy.init_node(node_name)
    test_class.config = load_yaml(rospy.get_param("~config"))
    test_class.yarn = test_class.config["yarns"][0]
    test_class.states = record_states()
    assert test_class.states.wait_for_first(), "no yarn_states within 15 s"


def measured_rate(records):
    """Messages per wall second over a list of (receive time, msg)."""
    if len(records) < 2:
        return 0.0
    return (len(records) - 1) / (records[-1][0] - records[0][0])


class MovingFrame:
    """Broadcasts `parent` -> `child` through tf2 every `period` [s] until stop(): the
    translation is `translation(stamp)` [m] for the transform's stamp (rospy.Time), no rotation."""

    def __init__(self, child, translation, parent="world", period=0.01):
        import tf2_ros

        self._broadcaster = tf2_ros.TransformBroadcaster()
        self._child, self._parent, self._period = child, parent, period
        self._translation = translation
        self._running = True
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def stop(self):
        self._running = False

    def _run(self):
        from geometry_msgs.msg import TransformStamped

        while self._running and not rospy.is_shutdown():
            transform = TransformStamped()
            transform.header.stamp = rospy.Time.now()
            transform.header.frame_id = self._parent
            transform.child_frame_id = self._child
            t = transform.transform.translation
            t.x, t.y, t.z = self._translation(transform.header.stamp)
            transform.transform.rotation.w = 1.0
            self._broadcaster.sendTransform(transform)
            time.sleep(self._period)
