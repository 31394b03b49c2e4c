#!/usr/bin/python3
"""The fabric demo (launch/fabric_demo.launch) tears as a trouser test should: every break names
the demo's fabric and a weft segment on the slit's line, the weft yarns tear one after another
from the slit's end towards the held row, each once, each at a finite, positive tension, up to
the weft yarn next to the held row (where the demo ends)."""
import math
import unittest

import rospy
import rostest
from yarn_tearing.msg import BreakEvent, FabricStateArray

import yarn_rostest_support as support

WALL_TIMEOUT = 170.0  # [s] the demo simulates ~4.8 s; a busy 2-core machine runs it slower


class FabricDemoTest(unittest.TestCase):
    def test_tear_runs_up_the_slit_to_the_held_row(self):
        rospy.init_node("fabric_demo_test")
        fabric = support.load_yaml(rospy.get_param("~config"))["fabrics"][0]
        slit = fabric["slits"][0]
        states = support.TopicRecorder("fabric_states", FabricStateArray)
        breaks = support.TopicRecorder("break_events", BreakEvent)
        self.assertTrue(states.wait_for_first(30.0), "no fabric_states")
        self.assertEqual(len(states.latest().fabrics[0].positions), fabric["ends"] * fabric["picks"])

        # The supervisor's end: the weft yarn next to the held first row has torn.
        def crossed():
            return any(e.fabric_yarn == 1 and e.family == BreakEvent.FAMILY_WEFT
                       for e in breaks.messages())
        self.assertTrue(support.wait_until(crossed, WALL_TIMEOUT), "the tear did not cross")

        events = breaks.messages()
        for e in events:
            self.assertEqual(e.fabric, fabric["name"])
            self.assertEqual(e.family, BreakEvent.FAMILY_WEFT)
            self.assertEqual(e.segment, slit["segment"], "a break off the slit's line")
            self.assertTrue(math.isfinite(e.tension) and e.tension > 0.0, e.tension)
            self.assertTrue(math.isfinite(e.strain) and e.strain > 0.0, e.strain)
        torn = [e.fabric_yarn for e in events]
        # It starts at the slit's end (the weft yarn above its first) and tears each weft yarn
        # from there to yarn 1 once.
        self.assertEqual(torn[0], slit["first_yarn"] - 1)
        self.assertEqual(sorted(torn, reverse=True), list(range(slit["first_yarn"] - 1, 0, -1)))
        times = [e.sim_time for e in events]
        self.assertEqual(times, sorted(times))


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "fabric_demo", FabricDemoTest)
