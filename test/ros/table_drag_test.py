#!/usr/bin/python3
"""A yarn on a table (a box, mu = 0.3) dragged along itself by its last vertex, grasped on a tf
frame that moves at `speed` for `travel_time` simulated seconds (scripts/gripper, ~motion tf,
/use_sim_time): whatever the node's real-time factor, it stays a drag.

- the mean pull on the gripper while sliding is mu * g * (the mass the table carries) within 10 %,
- no vertex moves faster than 1.2 x the gripper,
- the far end stays behind the gripper by at least 0.95 of the yarn's length.
Times are the states' stamps (simulated time under /use_sim_time)."""
import math
import unittest

import rospy
import rostest
import yaml
from std_msgs.msg import String

import yarn_rostest_support as support

PULL_TOLERANCE = 0.10
SPEED_FACTOR = 1.2
TRAIL_FRACTION = 0.95
SETTLE = 0.5        # [s] simulated after the grasp before the pull is averaged (taut, sliding)
GRAVITY = 9.81      # [m/s^2] as in the config


class TableDragTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        support.start_client(cls, "table_drag_test")
        cls.speed = float(rospy.get_param("~speed"))
        cls.travel_time = float(rospy.get_param("~travel_time"))
        materials = rospy.wait_for_message("yarn_materials", String, timeout=5.0)
        cls.material = yaml.safe_load(materials.data)["yarn"]

    def grasped(self, yarn):
        return (len(yarn.positions) - 1) in list(yarn.support_vertices)

    def test_drag_stays_a_drag(self):
        def done():
            states = [m for _, m in self.states.records()]
            grasp = [m.header.stamp.to_sec() for m in states
                     if self.grasped(support.find_yarn(m, "yarn"))]
            return grasp and states[-1].header.stamp.to_sec() > grasp[0] + self.travel_time + 0.2
        self.assertTrue(support.wait_until(done, timeout=40.0), "the drag did not finish")
        records = [m for _, m in self.states.records()]
        yarn_of = [(m.header.stamp.to_sec(), support.find_yarn(m, "yarn")) for m in records]
        start = next(t for t, y in yarn_of if self.grasped(y))
        sliding = [(t, y) for t, y in yarn_of
                   if start + SETTLE <= t <= start + self.travel_time - 0.05]
        self.assertGreater(len(sliding), 20, "too few states while sliding")

        n = len(yarn_of[0][1].positions)
        length = self.yarn["length"]
        mass = self.material["density"] * math.pi * self.material["radius"] ** 2 * length
        held = mass / (2.0 * (n - 1))  # the grasped end vertex's lumped mass: the gripper holds it
        expected = 0.3 * GRAVITY * (mass - held)
        pulls = [-y.support_forces[list(y.support_vertices).index(n - 1)].x for _, y in sliding]
        mean_pull = sum(pulls) / len(pulls)
        rospy.loginfo("table drag: mean pull %.4g N (mu m g %.4g N) over %d states", mean_pull,
                      expected, len(pulls))
        self.assertLess(abs(mean_pull - expected) / expected, PULL_TOLERANCE,
                        "mean pull %.4g N, expected %.4g N" % (mean_pull, expected))

        after = [(t, y) for t, y in yarn_of if t >= start]
        fastest, when, vertex = max((support.vector_norm(v), t - start, i)
                                    for t, y in after for i, v in enumerate(y.velocities))
        self.assertLessEqual(fastest, SPEED_FACTOR * self.speed,
                             "vertex %d moved at %.4g m/s %.3f s after the grasp (gripper %.4g "
                             "m/s)" % (vertex, fastest, when, self.speed))
        for t, y in sliding:
            trail = y.positions[-1].x - y.positions[0].x
            self.assertGreaterEqual(trail, TRAIL_FRACTION * length,
                                    "at t = %.3f s the far end is %.4g m behind the gripper" %
                                    (t, trail))
        end = yarn_of[-1][1].positions[-1].x - yarn_of[0][1].positions[-1].x
        self.assertAlmostEqual(end, self.speed * self.travel_time, delta=0.02 * self.speed *
                               self.travel_time, msg="the gripper travelled %.4g m" % end)


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "table_drag", TableDragTest)
