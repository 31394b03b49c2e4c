"""What the live measurements (tools/measure_table_drag.py, tools/measure_fabric_draw.py) share:
a scene launched with roslaunch on a master of its own (a free port), a rospy node listening to
it, and the node's /diagnostics reports."""
import contextlib
import os
import socket
import subprocess
import sys
import time

STARTUP = 30.0  # [s] wall: the master up


def free_port():
    with socket.socket() as sock:
        sock.bind(("localhost", 0))
        return sock.getsockname()[1]


def values_of(status):
    return {item.key: item.value for item in status.values}


def wait(predicate, timeout):
    """Polls `predicate` every 50 ms for at most `timeout` [s] wall; returns its last value."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline and not predicate():
        time.sleep(0.05)
    return predicate()


@contextlib.contextmanager
def launched(launch_file, *launch_args, node_name="measure_live"):
    """roslaunch yarn_tearing <launch_file> <launch_args> on a master of its own; inside, this
    process is a rospy node of it (one per process). Ends the launch on exit."""
    port = free_port()
    os.environ["ROS_MASTER_URI"] = "http://localhost:%d" % port
    launch = subprocess.Popen(["roslaunch", "-p", str(port), "yarn_tearing", launch_file]
                              + list(launch_args),
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        import rosgraph
        wait(rosgraph.is_master_online, STARTUP)
        import rospy
        rospy.init_node(node_name, anonymous=True, disable_signals=True)
        yield rospy
    finally:
        launch.terminate()
        try:
            launch.wait(timeout=15.0)
        except subprocess.TimeoutExpired:
            launch.kill()
            launch.wait()


class Diagnostics:
    """Records the node's simulation status reports: (wall receive time, values)."""

    def __init__(self, rospy):
        from diagnostic_msgs.msg import DiagnosticArray
        self.reports = []
        rospy.Subscriber("/diagnostics", DiagnosticArray, self._on_message, queue_size=100)

    def _on_message(self, message):
        for status in message.status:
            if status.name.endswith("simulation"):
                self.reports.append((time.monotonic(), values_of(status)))

    def dropped_between(self, wall0, wall1):
        """Steps the node dropped between two wall times (from its running total)."""
        before = [v for w, v in self.reports if w <= wall0]
        after = [v for w, v in self.reports if w <= wall1 + 1.5]
        first = int(before[-1].get("dropped steps (total)", 0)) if before else 0
        last = int(after[-1].get("dropped steps (total)", 0)) if after else first
        return last - first

    def during(self, wall0, wall1, key):
        return [v[key] for w, v in self.reports if wall0 < w <= wall1 + 1.0 and key in v]


def run_each(script, arguments, defaults, measure):
    """main() of a measurement `script` (its __file__): measure(argument) for each command-line
    argument (or each of `defaults`), each in a process of its own, since rospy initializes one
    node per process. Returns the exit status: 0, or 1 when a scene could not be run."""
    arguments = arguments or [str(a) for a in defaults]
    if len(arguments) == 1:
        return 0 if measure(arguments[0]) else 1
    statuses = [subprocess.call([sys.executable, script, a]) for a in arguments]
    return 0 if all(status == 0 for status in statuses) else 1
