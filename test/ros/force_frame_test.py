#!/usr/bin/python3
"""Through topics only: an applied force given in another tf frame (`rotated`, a static frame
turned 90 deg about z, broadcast by scripts/static_frame) is rotated into the world frame; a
force with a duration lapses; a zero force clears.

The weightless yarn lies along +y, pinned at its first vertex. +x in `rotated` is +y in world, so
F along rotated +x pulls the yarn straight: the pin then feels (0, F, 0) and nothing moves.
-y in `rotated` is +x in world: the free end starts to swing towards +x."""
import math
import statistics
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Vector3
from yarn_tearing.msg import AppliedForce

import yarn_rostest_support as support

FORCE = 2.0          # [N] along the yarn
SIDE_FORCE = 0.02    # [N] across the yarn: gentle, so the 1 g end swings slowly (20 m/s^2)
TOLERANCE = 0.02     # relative, on the support force


class ForceFrameTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        support.start_client(cls, "force_frame_test")
        cls.force_pub = rospy.Publisher("applied_force", AppliedForce, queue_size=10)
        assert support.wait_until(lambda: cls.force_pub.get_num_connections() > 0, 10.0)

    def send(self, force, duration=0.0, frame="rotated"):
        msg = AppliedForce()
        msg.header.stamp = rospy.Time(0)
        msg.header.frame_id = frame
        msg.yarn, msg.vertex, msg.force, msg.duration = self.yarn["name"], -1, Vector3(*force), duration
        self.force_pub.publish(msg)

    def current(self):
        return support.find_yarn(self.states.latest(), self.yarn["name"])

    def support_force(self):
        yarn = self.current()
        self.assertEqual(list(yarn.support_vertices), [0])
        return yarn.support_forces[0]

    def median_support_force(self, seconds):
        """Component-wise median of the pin's support force over the last `seconds` (the
        per-step estimate is noisy by a few percent)."""
        records = self.states.records(since=time.monotonic() - seconds)
        forces = [support.find_yarn(m, self.yarn["name"]).support_forces[0] for _, m in records]
        self.assertGreater(len(forces), 5)
        return [statistics.median(getattr(f, axis) for f in forces) for axis in "xyz"]

    def test_1_rotated_force_pulls_along_the_yarn_then_lapses(self):
        # The node refuses the force until its tf listener has the static frame: resend.
        def pulled():
            self.send((FORCE, 0.0, 0.0), duration=1.5)
            time.sleep(0.1)
            return self.support_force().y > 0.5 * FORCE
        self.assertTrue(support.wait_until(pulled, timeout=10.0, period=0.2), "force not applied")
        time.sleep(0.5)
        fx, fy, fz = self.median_support_force(0.4)
        self.assertAlmostEqual(fy, FORCE, delta=TOLERANCE * FORCE)
        self.assertLess(math.hypot(fx, fz), TOLERANCE * FORCE)
        end = self.current().positions[-1]
        self.assertLess(math.hypot(end.x, end.z), 1.0e-3, "the yarn must stay straight along +y")
        self.assertAlmostEqual(end.y, self.yarn["length"], delta=0.01 * self.yarn["length"])
        # duration 1.5 s: the force lapses by itself.
        self.assertTrue(support.wait_until(lambda: support.vector_norm(self.support_force()) <
                                           0.01 * FORCE, timeout=5.0), "force did not lapse")

    def test_2_rotated_force_swings_towards_world_x_then_clears(self):
        self.send((0.0, -SIDE_FORCE, 0.0))  # rotated -y = world +x
        self.assertTrue(support.wait_until(lambda: self.current().positions[-1].x > 0.005,
                                           timeout=5.0), "the free end did not move towards +x")
        end = self.current().velocities[-1]
        self.assertGreater(end.x, abs(end.z))
        self.send((0.0, 0.0, 0.0))  # zero clears the force
        time.sleep(0.5)
        yarn = self.current()
        self.assertTrue(support.state_is_finite(self.states.latest()))
        # Without the force nothing but the yarn's own motion is left: no pull along -x any more
        # (the pin only feels the centripetal pull of the swinging yarn, along the yarn).
        f = yarn.support_forces[0]
        p = yarn.positions[1]
        along = (f.x * p.x + f.y * p.y + f.z * p.z) / max(support.vector_norm(p), 1e-9)
        self.assertGreater(along, -1.0e-6)
        self.assertAlmostEqual(support.vector_norm(f), abs(along), delta=0.05 * SIDE_FORCE)


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "force_frame", ForceFrameTest)
