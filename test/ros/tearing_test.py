#!/usr/bin/python3
"""Through topics only: force_ramp pulls a pinned yarn until it tears; the break event's tension
matches the closed-form breaking tension sigma_b * pi * r^2 from this test's own config (2 %), and
force_ramp then ends; /diagnostics counts the step after the tear as taken in substeps (the
recoil, doc/method.md, "Recoil substeps") and reports the Newton systems' factorizations and
analyses a step; ~get_break_events returns the published event, numbered 0, and ~reset clears
its log."""
import math
import unittest

import rosnode
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from std_srvs.srv import Empty
from yarn_tearing.srv import GetBreakEvents

import yarn_rostest_support as support

TOLERANCE = 0.02
NODE = "/yarn_tearing"


class TearingTest(unittest.TestCase):
    def test_force_ramp_tears_at_breaking_tension(self):
        rospy.init_node("tearing_test")
        config = support.load_yaml(rospy.get_param("~config"))
        yarn = config["yarns"][0]
        breaking_stress = yarn["material"]["stress_strain"][-1][1]  # sigma_b [Pa]
        breaking_tension = breaking_stress * math.pi * yarn["radius"] ** 2  # [N]

        breaks = support.record_breaks()
        diagnostics = support.TopicRecorder("/diagnostics", DiagnosticArray)
        self.assertTrue(support.wait_until(breaks.messages, timeout=40.0), "no break_events")
        rospy.sleep(0.5)  # any further (wrong) events
        events = breaks.messages()
        self.assertEqual(len(events), 1, "one break expected, got %d" % len(events))
        event = events[0]
        self.assertEqual(event.yarn, yarn["name"])
        self.assertEqual(event.header.frame_id, config["frame_id"])
        self.assertGreater(event.header.stamp.to_sec(), 0.0)
        self.assertTrue(0 <= event.edge < yarn["num_vertices"] - 1)
        self.assertEqual((event.vertex_a, event.vertex_b), (event.edge, event.edge + 1))
        self.assertLess(abs(event.tension - breaking_tension) / breaking_tension, TOLERANCE,
                        "tension %.4f N at the break, expected sigma_b pi r^2 = %.4f N"
                        % (event.tension, breaking_tension))
        self.assertLess(abs(event.stress - breaking_stress) / breaking_stress, TOLERANCE)
        self.assertAlmostEqual(event.strain, yarn["material"]["stress_strain"][-1][0],
                               delta=TOLERANCE * yarn["material"]["stress_strain"][-1][0])
        self.assertAlmostEqual(event.position.x, yarn["start"][0], delta=1.0e-3)
        self.assertLess(event.position.z, yarn["start"][2])

        # force_ramp, like a testing machine whose specimen tore, has cleared its force and ended
        def ramp_ended():  # its process no longer answers (the master may still list it)
            return not rosnode.rosnode_ping("/force_ramp", max_count=1)

        self.assertTrue(support.wait_until(ramp_ended, timeout=10.0),
                        "force_ramp still running after its yarn tore")

        def substepped_steps():  # summed over the reports so far (each counts since the last)
            return sum(int(value.value) for array in diagnostics.messages()
                       for status in array.status for value in status.values
                       if value.key == "substepped steps")

        self.assertTrue(support.wait_until(lambda: substepped_steps() >= 1, timeout=5.0),
                        "/diagnostics never counted the tear's recoil step as substepped")
        # Each report gives the Newton systems' mean factorizations and analyses a step: finite,
        # and no more analyses than factorizations (only a factorized system is analysed).
        for array in diagnostics.messages():
            for status in array.status:
                values = {value.key: value.value for value in status.values}
                factorizations = float(values["mean factorizations per step [-]"])
                analyses = float(values["mean symbolic analyses per step [-]"])
                self.assertTrue(math.isfinite(factorizations) and factorizations >= 0.0)
                self.assertTrue(0.0 <= analyses <= factorizations, (analyses, factorizations))

        # A consumer that lost events fetches them: the log holds exactly what was published.
        get_break_events = rospy.ServiceProxy(NODE + "/get_break_events", GetBreakEvents)
        get_break_events.wait_for_service(timeout=10.0)
        self.assertEqual(event.index, 0)
        logged = get_break_events(first=0)
        self.assertEqual((logged.first, logged.total), (0, 1))
        self.assertEqual(logged.events, [event])
        newer = get_break_events(first=1)
        self.assertEqual((newer.events, newer.first, newer.total), ([], 1, 1))
        rospy.ServiceProxy(NODE + "/reset", Empty)()
        cleared = get_break_events(first=0)
        self.assertEqual((cleared.events, cleared.total), ([], 0), "~reset keeps old events")


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "tearing", TearingTest)
