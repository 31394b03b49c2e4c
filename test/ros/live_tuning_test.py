#!/usr/bin/python3
"""Through topics and dynamic_reconfigure only: the node's live-tunable parameters act while it
runs. real_time_factor 0.5 halves the simulated seconds per wall second; publish_rate 10 Hz gives
10 states per second; `dynparam set ... paused true` stops simulated time; with breaking_enabled
false a force twice the breaking force tears nothing, and switched back on it tears the yarn;
air_damping and regularization come back as set, an air_damping that would make the explicit
drag unstable is refused, and a nan real_time_factor, publish_rate or regularization is refused."""
import math
import subprocess
import time
import unittest

import dynamic_reconfigure.client
import roslib.packages
import rospy
import rostest
from geometry_msgs.msg import Vector3
from yarn_tearing.msg import AppliedForce

import yarn_rostest_support as support

NODE = "/yarn_tearing"
RATE_TOLERANCE = 0.15  # relative: wall pacing on a busy 2-core machine
MEASURE = 3.0          # [s] wall


class LiveTuningTest(unittest.TestCase):
    def sim_rate(self, states):
        """Simulated seconds per wall second over MEASURE wall seconds."""
        start = time.monotonic()
        time.sleep(MEASURE)
        records = states.records(since=start)
        self.assertGreater(len(records), 5)
        (t0, first), (t1, last) = records[0], records[-1]
        return (last.sim_time - first.sim_time) / (t1 - t0)

    def test_live_tuning(self):
        rospy.init_node("live_tuning_test")
        yarn = support.load_yaml(rospy.get_param("~config"))["yarns"][0]
        states = support.record_states()
        breaks = support.record_breaks()
        self.assertTrue(states.wait_for_first(), "no yarn_states")
        client = dynamic_reconfigure.client.Client(NODE, timeout=10.0)

        client.update_configuration({"real_time_factor": 0.5})
        time.sleep(0.5)
        self.assertAlmostEqual(self.sim_rate(states), 0.5, delta=0.5 * RATE_TOLERANCE)

        client.update_configuration({"real_time_factor": 1.0, "publish_rate": 10.0})
        time.sleep(0.5)
        start = time.monotonic()
        time.sleep(MEASURE)
        measured = support.measured_rate(states.records(since=start))
        self.assertAlmostEqual(measured, 10.0, delta=10.0 * RATE_TOLERANCE)

        # = rosrun dynamic_reconfigure dynparam set ..., with Debian's python (dynparam's
        # "/usr/bin/env python3" may find a pyenv interpreter without roslib)
        dynparam = roslib.packages.find_node("dynamic_reconfigure", "dynparam")[0]
        subprocess.run(["/usr/bin/python3", dynparam, "set", NODE, "paused", "true"], check=True,
                       timeout=30.0)
        time.sleep(0.5)
        paused_at = states.latest().sim_time
        time.sleep(1.0)
        self.assertEqual(states.latest().sim_time, paused_at, "simulated time ran while paused")
        client.update_configuration({"paused": False})
        time.sleep(1.0)
        self.assertGreater(states.latest().sim_time, paused_at + 0.5)

        # Twice the breaking force sigma_b pi r^2 on the free end: no tear while breaking is off.
        breaking_force = yarn["material"]["stress_strain"][-1][1] * math.pi * yarn["radius"] ** 2
        client.update_configuration({"breaking_enabled": False})
        force = rospy.Publisher("applied_force", AppliedForce, queue_size=10)
        support.wait_until(lambda: force.get_num_connections() > 0, timeout=5.0)
        force.publish(AppliedForce(yarn=yarn["name"], vertex=-1,
                                   force=Vector3(0.0, 0.0, -2.0 * breaking_force)))
        time.sleep(1.5)
        self.assertEqual(breaks.messages(), [], "tore with breaking_enabled false")
        client.update_configuration({"breaking_enabled": True})
        self.assertTrue(support.wait_until(breaks.messages, timeout=5.0), "no tear once enabled")

        config = client.update_configuration({"air_damping": 0.01, "regularization": 1.0e-4})
        self.assertEqual(config["air_damping"], 0.01)
        self.assertEqual(config["regularization"], 1.0e-4)
        self.assertEqual(rospy.get_param(NODE + "/air_damping"), 0.01)
        # explicit drag must stay below the mass per length / time_step (4.7e-2 N*s/m^2 here)
        config = client.update_configuration({"air_damping": 1.0})
        self.assertEqual(config["air_damping"], 0.01, "an unstable air_damping was accepted")

        # Values that are not numbers are refused as at start: the current ones stay in effect
        # and simulated time keeps running.
        for name in ("real_time_factor", "publish_rate", "regularization"):
            before = client.get_configuration(timeout=10.0)[name]
            subprocess.run(["/usr/bin/python3", dynparam, "set", NODE, name, "nan"], check=True,
                           timeout=30.0)
            after = client.get_configuration(timeout=10.0)[name]
            self.assertEqual(after, before, name + " nan was accepted")
        running_at = states.latest().sim_time
        time.sleep(1.0)
        self.assertGreater(states.latest().sim_time, running_at + 0.5, "stopped after nan")
        self.assertGreater(states.latest().header.stamp.to_sec(), 0.0)


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "live_tuning", LiveTuningTest)
