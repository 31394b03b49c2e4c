#!/usr/bin/python3
"""A weightless yarn drawn apart by two grasps whose motion is in their messages (scripts/gripper,
~motion message, both ends at once), the node as fast as possible under /use_sim_time:

- the yarn is strained at the planned rate (separation speed / length) within 5 %: the
  least-squares slope of its ends' distance over the states' stamps (simulated time) while both
  ends are drawn, before and after the tear (states are sampled: as fast as possible the node can
  run a hundred times faster than a Python subscriber reads), and the strain the ends' line gives
  at the tear's time is the breaking strain within 5 %;
- it tears at its breaking force (break_events' tension vs yarn_materials' weakest breaking
  force) within 2 %."""
import math
import unittest

import rospy
import rostest
import yaml
from std_msgs.msg import String
from yarn_tearing.srv import GetBreakEvents

import yarn_rostest_support as support

RATE_TOLERANCE = 0.05
FORCE_TOLERANCE = 0.02
MIN_SPANS = 10  # states with both ends drawn that the fit needs at least


def slope(points):
    """Least-squares slope of (x, y) points."""
    n = float(len(points))
    mx = sum(x for x, _ in points) / n
    my = sum(y for _, y in points) / n
    sxx = sum((x - mx) ** 2 for x, _ in points)
    return sum((x - mx) * (y - my) for x, y in points) / sxx


class GraspMotionTearTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        support.start_client(cls, "grasp_motion_tear_test")
        cls.break_log = rospy.ServiceProxy("/yarn_tearing/get_break_events", GetBreakEvents)
        materials = rospy.wait_for_message("yarn_materials", String, timeout=5.0)
        cls.material = yaml.safe_load(materials.data)["yarn"]
        cls.speed = float(rospy.get_param("~separation_speed"))

    def drawn_spans(self):
        """(stamp [s], distance of the ends [m]) of each recorded state in which both ends are
        held and drawn apart (the jaws are grasped still, then started; they go on after the
        tear)."""
        both = {0, self.yarn["num_vertices"] - 1}
        half = 0.5 * self.speed
        spans = []
        for _, states in self.states.records():
            yarn = support.find_yarn(states, "yarn")
            moving = all(abs(yarn.velocities[v].x) > 0.9 * half for v in both)
            if both <= set(yarn.support_vertices) and moving:
                a, b = yarn.positions[0], yarn.positions[-1]
                spans.append((states.header.stamp.to_sec(),
                              math.sqrt((b.x - a.x) ** 2 + (b.y - a.y) ** 2 + (b.z - a.z) ** 2)))
        return spans

    def test_tear_at_planned_rate_and_breaking_force(self):
        # the node's break log, not the topic: as fast as possible the yarn can tear before a
        # subscription to break_events is wired
        rospy.wait_for_service("/yarn_tearing/get_break_events", timeout=10.0)
        self.assertTrue(support.wait_until(lambda: self.break_log(0).events, timeout=40.0),
                        "the yarn did not tear")
        tear = self.break_log(0).events[0]
        # States after the tear too (the jaws go on). The recorder samples the states (they come
        # faster than Python reads them), so how many fall into a span of simulated time depends
        # on the load: it waits for enough of them instead.
        support.wait_until(lambda: self.states.latest().header.stamp.to_sec() >
                           tear.sim_time + 1.0 and len(self.drawn_spans()) > MIN_SPANS,
                           timeout=10.0, period=0.2)
        length = self.yarn["length"]
        spans = self.drawn_spans()
        records = self.states.records()
        self.assertGreater(len(spans), MIN_SPANS, "%d states with both ends drawn apart (%d states "
                           "from %.3f s to %.3f s, tear at %.3f s)" %
                           (len(spans), len(records), records[0][1].header.stamp.to_sec(),
                            records[-1][1].header.stamp.to_sec(), tear.sim_time))
        planned = self.speed / length
        achieved = slope(spans) / length
        # the yarn's strain when it tore, from the ends' straight line at the tear's time
        t0, s0 = spans[0]
        strain = (s0 + slope(spans) * (tear.sim_time - t0)) / length - 1.0
        rospy.loginfo("drawn apart: strain rate %.4g /s (planned %.4g /s), strain %.4g at the "
                      "tear (breaking strain %.4g), tore at %.4g N (breaking force %.4g N) at "
                      "t = %.4f s", achieved, planned, strain, self.material["breaking_strain"],
                      tear.tension, self.material["weakest_breaking_force"], tear.sim_time)
        self.assertLess(abs(achieved - planned) / planned, RATE_TOLERANCE,
                        "strain rate %.4g /s, planned %.4g /s" % (achieved, planned))
        self.assertLess(abs(strain - self.material["breaking_strain"]) /
                        self.material["breaking_strain"], RATE_TOLERANCE,
                        "strain %.4g at the tear, breaking strain %.4g" %
                        (strain, self.material["breaking_strain"]))
        breaking = self.material["weakest_breaking_force"]
        self.assertLess(abs(tear.tension - breaking) / breaking, FORCE_TOLERANCE,
                        "tore at %.4g N, breaking force %.4g N" % (tear.tension, breaking))


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "grasp_motion_tear", GraspMotionTearTest)
