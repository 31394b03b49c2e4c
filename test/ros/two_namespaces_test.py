#!/usr/bin/python3
"""Through topics only: two nodes under one master, in namespaces lab_a and lab_b, each publish
their own yarn_states; the force ramp in lab_a tears lab_a's yarn (its events on
/lab_a/break_events) and nothing reaches lab_b, whose yarn keeps hanging with all its edges."""
import unittest

import rospy
import rostest

import yarn_rostest_support as support


class TwoNamespacesTest(unittest.TestCase):
    def test_each_namespace_is_its_own_simulation(self):
        rospy.init_node("two_namespaces_test")
        states_a = support.record_states("/lab_a/yarn_states")
        states_b = support.record_states("/lab_b/yarn_states")
        breaks_a = support.record_breaks("/lab_a/break_events")
        breaks_b = support.record_breaks("/lab_b/break_events")
        self.assertTrue(states_a.wait_for_first(), "no /lab_a/yarn_states")
        self.assertTrue(states_b.wait_for_first(), "no /lab_b/yarn_states")
        self.assertEqual([y.name for y in states_a.latest().yarns], ["specimen"])
        self.assertEqual([y.name for y in states_b.latest().yarns], ["hanging"])

        self.assertTrue(support.wait_until(breaks_a.messages, timeout=40.0), "lab_a never tore")
        rospy.sleep(1.0)  # anything that would (wrongly) reach lab_b
        # (how often lab_a tears is tearing.test's concern; here: whose events they are)
        self.assertEqual({e.yarn for e in breaks_a.messages()}, {"specimen"})
        self.assertEqual(breaks_b.messages(), [], "lab_b tore")
        hanging = states_b.latest().yarns[0]
        self.assertFalse(any(hanging.broken), "a lab_b edge is cut")
        self.assertGreater(states_b.latest().sim_time, 1.0)


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "two_namespaces", TwoNamespacesTest)
