#!/usr/bin/python3
"""Through topics only: yarn_states arrive at publish_rate (+-10 %) with consistent contents, and
bad applied_force / grasp messages are refused while the states keep coming (rate holds, no NaN,
nothing moves)."""
import math
import time
import unittest

import rospy
import rostest
import yaml
from geometry_msgs.msg import Vector3
from std_msgs.msg import String
from yarn_tearing.msg import AppliedForce, Grasp

import yarn_rostest_support as support

RATE_TOLERANCE = 0.10
MEASURE_SECONDS = 3.0


class StateRateAndBadInputTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        support.start_client(cls, "state_rate_and_bad_input_test")
        cls.force_pub = rospy.Publisher("applied_force", AppliedForce, queue_size=100)
        cls.grasp_pub = rospy.Publisher("grasp", Grasp, queue_size=100)
        time.sleep(0.5)  # let the yarn settle under gravity

    def expected_weight(self):
        """Weight of the whole yarn [N], closed form from the config."""
        radius = self.yarn["radius"]
        mass = self.yarn["material"]["density"] * math.pi * radius ** 2 * self.yarn["length"]
        return mass * -self.config["gravity"][2]

    def check_rate(self, start):
        records = self.states.records(since=start)
        rate = support.measured_rate(records)
        expected = self.config["publish_rate"]
        self.assertLess(abs(rate - expected) / expected, RATE_TOLERANCE,
                        "yarn_states at %.2f Hz, expected %.1f Hz" % (rate, expected))
        return records

    def check_at_rest(self, states):
        """The yarn still hangs from its pin, carrying its own weight only."""
        yarn = support.find_yarn(states, self.yarn["name"])
        self.assertEqual(list(yarn.support_vertices), [0])
        support_force = yarn.support_forces[0]
        weight = self.expected_weight()
        self.assertAlmostEqual(support_force.z, -weight, delta=0.05 * weight)
        self.assertLess(math.hypot(support_force.x, support_force.y), 0.05 * weight)
        for velocity in yarn.velocities:
            self.assertLess(support.vector_norm(velocity), 1.0e-3)

    def test_1_states_rate_and_contents(self):
        start = time.monotonic()
        time.sleep(MEASURE_SECONDS)
        records = self.check_rate(start)
        stamps = [m.header.stamp.to_sec() for _, m in records]
        self.assertTrue(all(b > a for a, b in zip(stamps, stamps[1:])), "stamps must increase")
        states = records[-1][1]
        self.assertEqual(states.header.frame_id, self.config["frame_id"])
        yarn = support.find_yarn(states, self.yarn["name"])
        n = self.yarn["num_vertices"]
        self.assertEqual(len(yarn.positions), n)
        self.assertEqual(len(yarn.velocities), n)
        self.assertEqual(list(yarn.edge_vertices), [i + d for i in range(n - 1) for d in (0, 1)])
        for field in (yarn.rest_lengths, yarn.tensions, yarn.stresses, yarn.strains,
                      yarn.plastic_strains, yarn.strain_limits, yarn.broken):
            self.assertEqual(len(field), n - 1)
        self.assertAlmostEqual(yarn.positions[-1].z, -self.yarn["length"], delta=1.0e-3)
        self.assertTrue(support.state_is_finite(states))
        self.check_at_rest(states)

    def test_2_yarn_materials_latched(self):
        msg = rospy.wait_for_message("yarn_materials", String, timeout=5.0)
        materials = yaml.safe_load(msg.data)
        entry = materials[self.yarn["name"]]
        curve = self.yarn["material"]["stress_strain"]
        self.assertAlmostEqual(entry["breaking_stress"], curve[-1][1], delta=1.0)
        self.assertAlmostEqual(entry["breaking_strain"], curve[-1][0])
        self.assertAlmostEqual(entry["yield_stress"], curve[1][1], delta=1.0)
        self.assertAlmostEqual(entry["youngs_modulus"], curve[1][1] / curve[1][0], delta=1.0)
        self.assertAlmostEqual(entry["area"], math.pi * self.yarn["radius"] ** 2)
        self.assertEqual([list(p) for p in entry["curve"]], curve)

    def bad_messages(self):
        name = self.yarn["name"]

        def force(yarn=name, vertex=-1, f=(0.0, 0.0, -1.0), frame="", duration=0.0,
                  rate=(0.0, 0.0, 0.0), ramp_duration=0.0):
            msg = AppliedForce()
            msg.header.frame_id = frame
            msg.yarn, msg.vertex, msg.force, msg.duration = yarn, vertex, Vector3(*f), duration
            msg.force_rate, msg.ramp_duration = Vector3(*rate), ramp_duration
            return self.force_pub, msg

        def grasp(yarn=name, vertex=-1, frame="world", release=False):
            msg = Grasp()
            msg.yarn, msg.vertex, msg.target_frame, msg.release = yarn, vertex, frame, release
            return self.grasp_pub, msg

        nan, inf = float("nan"), float("inf")
        return [
            force(f=(nan, 0.0, 0.0)), force(f=(0.0, inf, 0.0)), force(f=(0.0, 0.0, -inf)),
            force(yarn="no_such_yarn"), force(vertex=999), force(vertex=-999),
            force(frame="no_such_frame"), force(duration=-1.0), force(duration=nan),
            force(rate=(0.0, nan, 0.0)), force(rate=(0.0, 0.0, -1.0e12)),
            force(ramp_duration=-1.0), force(ramp_duration=inf),
            grasp(yarn="no_such_yarn"), grasp(vertex=999), grasp(frame="no_such_frame"),
            grasp(frame=""), grasp(vertex=3, release=True),
        ]

    def test_3_bad_messages_refused(self):
        messages = self.bad_messages()
        start = time.monotonic()
        while time.monotonic() - start < MEASURE_SECONDS:
            for publisher, msg in messages:
                msg.header.stamp = rospy.Time(0)
                publisher.publish(msg)
            time.sleep(0.05)
        records = self.check_rate(start)
        for _, states in records:
            self.assertTrue(support.state_is_finite(states), "NaN or inf in yarn_states")
        time.sleep(0.3)
        self.check_at_rest(self.states.latest())


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "state_rate_and_bad_input", StateRateAndBadInputTest)
