"""Measures the node's achieved real-time factor in a user's scene, through its topics: the table
drag of test/ros/config/table_drag.yaml (a 0.5 m, 50-vertex cotton yarn dragged 20 cm at 5 cm/s
over a box, mu = 0.3, by a gripper on a tf frame, under /use_sim_time), launched with
test/ros/table_drag.test on a master of its own (a free port).

For each real-time factor given (default: 1 and 0) it prints, while the yarn is dragged, the
achieved real-time factor (simulated seconds of the states' stamps per wall second, and the median
of the node's /diagnostics "achieved real-time factor"), the steps the node dropped, its largest
lag behind schedule and the costliest stage of its loop. It reports and never fails on the
figures (exit 0); it exits 1 only when the scene cannot be run.

  tools/measure_table_drag.sh [real_time_factor ...]"""
import os
import socket
import statistics
import subprocess
import sys
import time

DRAG_TIME = 4.0      # [s] simulated: the gripper's travel time in table_drag.test
STARTUP = 30.0       # [s] wall: the node and the gripper up, the yarn grasped
RUN_TIMEOUT = 40.0   # [s] wall: longest one factor's drag may take


def free_port():
    with socket.socket() as sock:
        sock.bind(("localhost", 0))
        return sock.getsockname()[1]


def values_of(status):
    return {item.key: item.value for item in status.values}


class Measurement:
    def __init__(self):
        import rospy
        from diagnostic_msgs.msg import DiagnosticArray
        from yarn_tearing.msg import YarnStateArray

        self.rospy = rospy
        self.states = []       # (wall, sim time, grasped)
        self.reports = []      # (wall, values)
        rospy.Subscriber("yarn_states", YarnStateArray, self.on_states, queue_size=100)
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics, queue_size=100)

    def on_states(self, message):
        yarn = message.yarns[0]
        grasped = (len(yarn.positions) - 1) in list(yarn.support_vertices)
        self.states.append((time.monotonic(), message.header.stamp.to_sec(), grasped))

    def on_diagnostics(self, message):
        for status in message.status:
            if status.name.endswith("simulation"):
                self.reports.append((time.monotonic(), values_of(status)))

    def grasp(self):
        return next(((w, t) for w, t, g in self.states if g), None)

    def wait(self, predicate, timeout):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline and not predicate():
            time.sleep(0.05)
        return predicate()


def measure(factor):
    port = free_port()
    os.environ["ROS_MASTER_URI"] = "http://localhost:%d" % port
    launch = subprocess.Popen(
        ["roslaunch", "-p", str(port), "yarn_tearing", "table_drag.test",
         "real_time_factor:=%g" % factor],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        import rosgraph
        deadline = time.monotonic() + STARTUP
        while not rosgraph.is_master_online() and time.monotonic() < deadline:
            time.sleep(0.1)
        import rospy
        rospy.init_node("measure_table_drag", anonymous=True, disable_signals=True)
        m = Measurement()
        if not m.wait(m.grasp, STARTUP):
            print("table drag, real_time_factor %g: the yarn was not grasped within %.0f s" %
                  (factor, STARTUP))
            return False
        wall0, sim0 = m.grasp()
        if not m.wait(lambda: m.states[-1][1] >= sim0 + DRAG_TIME, RUN_TIMEOUT):
            print("table drag, real_time_factor %g: the drag did not end within %.0f s" %
                  (factor, RUN_TIMEOUT))
            return False
        wall1, sim1 = m.states[-1][0], m.states[-1][1]
        m.wait(lambda: m.reports and m.reports[-1][0] > wall1, 3.0)  # the report after the drag
        during = [v for w, v in m.reports if wall0 < w <= wall1 + 1.0]
        before = [v for w, v in m.reports if w <= wall0]
        last = m.reports[-1][1] if m.reports else {}
        dropped_before = int(before[-1].get("dropped steps (total)", 0)) if before else 0
        dropped = int(last.get("dropped steps (total)", 0)) - dropped_before
        factors = [float(v["achieved real-time factor"]) for v in during
                   if "achieved real-time factor" in v]
        lags = [float(v.get("lag behind schedule [s]", 0.0)) for v in during]
        stages = [v.get("costliest stage", "?") for v in during]
        print("table drag, real_time_factor %g: achieved real-time factor %.3f (states: %.2f "
              "simulated s in %.2f wall s), /diagnostics median %s over %d reports "
              "(min %s, max %s); dropped steps while dragging %d (total %s); largest lag %.3f s; "
              "costliest stage %s" %
              (factor, (sim1 - sim0) / (wall1 - wall0), sim1 - sim0, wall1 - wall0,
               "%.3f" % statistics.median(factors) if factors else "-", len(factors),
               "%.3f" % min(factors) if factors else "-",
               "%.3f" % max(factors) if factors else "-", dropped,
               last.get("dropped steps (total)", "?"), max(lags) if lags else 0.0,
               max(set(stages), key=stages.count) if stages else "?"))
        return True
    finally:
        launch.terminate()
        try:
            launch.wait(timeout=15.0)
        except subprocess.TimeoutExpired:
            launch.kill()
            launch.wait()


def main():
    factors = [float(a) for a in sys.argv[1:]] or [1.0, 0.0]
    ok = True
    for factor in factors:
        # one process per factor: rospy initializes one node per process
        if len(factors) > 1:
            ok = subprocess.call([sys.executable, __file__, repr(factor)]) == 0 and ok
        else:
            ok = measure(factor)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
