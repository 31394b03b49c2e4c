"""Measures the node's achieved real-time factor through its topics while a fabric held by its
two top corners is drawn apart until it tears: test/ros/fabric_corners.launch (a size x size
cotton plain weave, 8 x 8 cm, its top corners pinned, then grasped by a gripper that draws them
apart along the weft at 2 cm/s each in simulated time; real_time_factor 1, /use_sim_time).

For each scene given (default: 16, 32, 16@1e-3 and 32@1e-3: SIZE without air, SIZE@AIR_DAMPING
with the node's air_damping [N s/m^2], 1e-3 being config/fabric.yaml's) it prints the achieved
real-time factor (simulated seconds of fabric_states' stamps per wall second) while the grippers
draw the patch before its first tear (from the simulated time stamped on the gripper's first
moving grasp), and over the tearing (from 0.1 s before the first tear to 0.5 s after the last),
the tears, the steps the node dropped and the costliest stage of its loop. It reports and never
fails on the figures (exit 0); it exits 1 only when a scene is malformed or cannot be run.

  tools/measure_live.sh fabric_draw [SIZE[@AIR_DAMPING] ...]"""
import sys
import time

from live_measurement import Diagnostics, launched, run_each, wait

DRAW_START = 0.3     # [s] simulated: the gripper grasps the corners (fabric_corners.launch)
STARTUP = 45.0       # [s] wall: longest wait for the states to pass the draw's start
FIRST_TEAR = 50.0    # [s] wall: longest wait for the first tear after it
QUIET_AFTER = 0.5    # [s] simulated without a tear: the tearing is over
RUN_TIMEOUT = 40.0   # [s] wall: longest the tearing may take


def factor(states, wall0, wall1):
    """Simulated seconds per wall second of the states received between two wall times."""
    inside = [(w, t) for w, t in states if wall0 <= w <= wall1]
    if len(inside) < 2 or inside[-1][0] <= inside[0][0]:
        return float("nan")
    return (inside[-1][1] - inside[0][1]) / (inside[-1][0] - inside[0][0])


def moving(grasp):
    """Whether a Grasp message carries a motion (the gripper's draw) rather than a hold."""
    v = grasp.velocity
    return not grasp.release and (v.x != 0.0 or v.y != 0.0 or v.z != 0.0)


def measure(size, air_damping):
    name = "fabric %d x %d%s" % (size, size, " in air (air_damping %g)" % air_damping
                                 if air_damping > 0.0 else "")
    with launched("fabric_corners.launch", "size:=%d" % size, "air_damping:=%r" % air_damping,
                  node_name="measure_fabric_draw") as rospy:
        from yarn_tearing.msg import BreakEvent, FabricStateArray, Grasp
        states = []  # (wall, sim time)
        tears = []   # (wall, sim time)
        draws = []   # sim time stamped on each moving grasp: the draw starts at the first
        rospy.Subscriber("fabric_states", FabricStateArray,
                         lambda m: states.append((time.monotonic(), m.header.stamp.to_sec())),
                         queue_size=100)
        rospy.Subscriber("break_events", BreakEvent,
                         lambda m: tears.append((time.monotonic(), m.sim_time)),
                         queue_size=10000)
        rospy.Subscriber("grasp", Grasp, lambda m: draws.append(m.header.stamp.to_sec())
                         if moving(m) else None, queue_size=100)
        diagnostics = Diagnostics(rospy)
        if not wait(lambda: draws and states and states[-1][1] >= draws[0], STARTUP):
            if len(states) < 2:
                print("%s: no states within %.0f s" % (name, STARTUP))
                return False
            print("%s held by its top corners: achieved real-time factor %.3f pinned, "
                  "to be grasped from %.1f s and drawn (t = %.3f s simulated after %.0f s wall, "
                  "%s; tears %d)" %
                  (name, factor(states, states[0][0], states[-1][0]), DRAW_START,
                   states[-1][1], STARTUP,
                   "drawn from %.3f s" % draws[0] if draws else "not yet drawn", len(tears)))
            return True
        drawn_from = next(w for w, t in states if t >= draws[0])
        if not wait(lambda: tears, FIRST_TEAR):
            print("%s: no tear within %.0f s" % (name, FIRST_TEAR))
            return False
        deadline = time.monotonic() + RUN_TIMEOUT
        while time.monotonic() < deadline and states[-1][1] < tears[-1][1] + QUIET_AFTER:
            time.sleep(0.05)
        first_wall, first_sim = tears[0]
        start = next((w for w, t in states if t >= first_sim - 0.1), first_wall)
        end = next((w for w, t in states if t >= tears[-1][1] + QUIET_AFTER), states[-1][0])
        stages = diagnostics.during(start, end, "costliest stage")
        print("%s held by its top corners, drawn apart at 2 cm/s each: achieved "
              "real-time factor %.3f drawn before the first tear, %.3f over the tearing "
              "(%d tears from t = %.3f to %.3f s simulated, %.1f s wall); dropped steps %d; "
              "costliest stage %s" %
              (name, factor(states, drawn_from, first_wall), factor(states, start, end),
               len(tears), first_sim, tears[-1][1], end - start,
               diagnostics.dropped_between(drawn_from, end),
               max(set(stages), key=stages.count) if stages else "?"))
        return True


def scene(argument):
    """SIZE or SIZE@AIR_DAMPING: (size, air damping [N s/m^2]); exits 1 on anything else."""
    size, _, air_damping = argument.partition("@")
    try:
        return int(size), float(air_damping or 0.0)
    except ValueError:
        sys.exit("measure_fabric_draw: '%s' is not SIZE or SIZE@AIR_DAMPING (16, 32@1e-3)"
                 % argument)


def main():
    return run_each(__file__, sys.argv[1:], ["16", "32", "16@1e-3", "32@1e-3"],
                    lambda argument: measure(*scene(argument)))


if __name__ == "__main__":
    sys.exit(main())
