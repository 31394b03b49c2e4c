#!/usr/bin/python3
"""A weightless yarn drawn apart by two grasps whose motion is in their messages (scripts/gripper,
~motion message, both ends at once), the node as fast as possible under /use_sim_time:

- the yarn's end-to-end strain grows at the planned rate (separation speed / length) within 5 %
  while it is drawn (a least-squares slope over the states' stamps, simulated time), and
- it tears at its breaking force (break_events' tension vs yarn_materials' weakest breaking
  force) within 2 %."""
import math
import unittest

import rospy
import rostest
import yaml
from std_msgs.msg import String

import yarn_rostest_support as support

RATE_TOLERANCE = 0.05
FORCE_TOLERANCE = 0.02
MARGIN = 0.01  # [s] simulated: states this near the grasp or the tear are left out of the fit


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
        cls.breaks = support.record_breaks()
        materials = rospy.wait_for_message("yarn_materials", String, timeout=5.0)
        cls.material = yaml.safe_load(materials.data)["yarn"]
        cls.speed = float(rospy.get_param("~separation_speed"))

    def test_tear_at_planned_rate_and_breaking_force(self):
        self.assertTrue(support.wait_until(lambda: self.breaks.messages(), timeout=40.0),
                        "the yarn did not tear")
        tear = self.breaks.messages()[0]
        length = self.yarn["length"]
        both = {0, self.yarn["num_vertices"] - 1}
        half = 0.5 * self.speed
        strains = []
        for _, states in self.states.records():
            yarn = support.find_yarn(states, "yarn")
            # both ends held and moving (the jaws are grasped still, then started)
            moving = all(abs(yarn.velocities[v].x) > 0.9 * half for v in both)
            if both <= set(yarn.support_vertices) and moving and not any(yarn.broken):
                a, b = yarn.positions[0], yarn.positions[-1]
                span = math.sqrt((b.x - a.x) ** 2 + (b.y - a.y) ** 2 + (b.z - a.z) ** 2)
                strains.append((states.header.stamp.to_sec(), span / length - 1.0))
        self.assertTrue(strains, "no state with both ends drawn apart before the tear")
        first, last = strains[0][0] + MARGIN, tear.sim_time - MARGIN
        drawn = [(t, e) for t, e in strains if first <= t <= last]
        self.assertGreater(len(drawn), 10, "too few states while drawn: %d" % len(drawn))
        planned = self.speed / length
        achieved = slope(drawn)
        rospy.loginfo("drawn apart: strain rate %.4g /s (planned %.4g /s), tore at %.4g N "
                      "(breaking force %.4g N) at t = %.4f s", achieved, planned, tear.tension,
                      self.material["weakest_breaking_force"], tear.sim_time)
        self.assertLess(abs(achieved - planned) / planned, RATE_TOLERANCE,
                        "strain rate %.4g /s, planned %.4g /s" % (achieved, planned))
        breaking = self.material["weakest_breaking_force"]
        self.assertLess(abs(tear.tension - breaking) / breaking, FORCE_TOLERANCE,
                        "tore at %.4g N, breaking force %.4g N" % (tear.tension, breaking))


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "grasp_motion_tear", GraspMotionTearTest)
