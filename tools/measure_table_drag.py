"""Measures the node's achieved real-time factor in a user's scene, through its topics: the table
drag of test/ros/config/table_drag.yaml (a 0.5 m, 50-vertex cotton yarn dragged 20 cm at 5 cm/s
over a box, mu = 0.3, by a gripper on a tf frame, under /use_sim_time), launched with
test/ros/table_drag.test on a master of its own (a free port).

For each real-time factor given (default: 1 and 0) it prints, while the yarn is dragged, the
achieved real-time factor (simulated seconds of the states' stamps per wall second, and the median
of the node's /diagnostics "achieved real-time factor"), the steps the node dropped, its largest
lag behind schedule and the costliest stage of its loop. It reports and never fails on the
figures (exit 0); it exits 1 only when the scene cannot be run.

  tools/measure_live.sh table_drag [real_time_factor ...]"""
import statistics
import sys
import time

from live_measurement import Diagnostics, launched, run_each, wait

DRAG_TIME = 4.0      # [s] simulated: the gripper's travel time in table_drag.test
STARTUP = 30.0       # [s] wall: the node and the gripper up, the yarn grasped
RUN_TIMEOUT = 40.0   # [s] wall: longest one factor's drag may take


def measure(factor):
    with launched("table_drag.test", "real_time_factor:=%g" % factor,
                  node_name="measure_table_drag") as rospy:
        from yarn_tearing.msg import YarnStateArray
        states = []  # (wall, sim time, grasped)

        def on_states(message):
            yarn = message.yarns[0]
            grasped = (len(yarn.positions) - 1) in list(yarn.support_vertices)
            states.append((time.monotonic(), message.header.stamp.to_sec(), grasped))

        rospy.Subscriber("yarn_states", YarnStateArray, on_states, queue_size=100)
        diagnostics = Diagnostics(rospy)

        def grasp():
            return next(((w, t) for w, t, g in states if g), None)

        if not wait(grasp, STARTUP):
            print("table drag, real_time_factor %g: the yarn was not grasped within %.0f s" %
                  (factor, STARTUP))
            return False
        wall0, sim0 = grasp()
        if not wait(lambda: states[-1][1] >= sim0 + DRAG_TIME, RUN_TIMEOUT):
            print("table drag, real_time_factor %g: the drag did not end within %.0f s" %
                  (factor, RUN_TIMEOUT))
            return False
        wall1, sim1 = states[-1][0], states[-1][1]
        wait(lambda: diagnostics.reports and diagnostics.reports[-1][0] > wall1, 3.0)
        factors = [float(v) for v in
                   diagnostics.during(wall0, wall1, "achieved real-time factor")]
        lags = [float(v) for v in diagnostics.during(wall0, wall1, "lag behind schedule [s]")]
        stages = diagnostics.during(wall0, wall1, "costliest stage")
        last = diagnostics.reports[-1][1] if diagnostics.reports else {}
        print("table drag, real_time_factor %g: achieved real-time factor %.3f (states: %.2f "
              "simulated s in %.2f wall s), /diagnostics median %s over %d reports "
              "(min %s, max %s); dropped steps while dragging %d (total %s); largest lag %.3f s; "
              "costliest stage %s" %
              (factor, (sim1 - sim0) / (wall1 - wall0), sim1 - sim0, wall1 - wall0,
               "%.3f" % statistics.median(factors) if factors else "-", len(factors),
               "%.3f" % min(factors) if factors else "-",
               "%.3f" % max(factors) if factors else "-",
               diagnostics.dropped_between(wall0, wall1),
               last.get("dropped steps (total)", "?"), max(lags) if lags else 0.0,
               max(set(stages), key=stages.count) if stages else "?"))
        return True


def main():
    return run_each(__file__, sys.argv[1:], [1.0, 0.0], lambda factor: measure(float(factor)))


if __name__ == "__main__":
    sys.exit(main())
