#!/usr/bin/python3
"""Under /use_sim_time with the node's own /clock: /diagnostics keeps its wall rate
through ~reset (ROS time jumps back to 0) and through pause/resume, without claiming the node is
slower than real_time_factor; back-to-back resets do not publish more states than publish_rate."""
import time
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from std_srvs.srv import Empty, SetBool

import yarn_rostest_support as support

NODE = "/yarn_tearing"
DIAGNOSTIC_PERIOD = 1.0  # [s, wall] diagnostic_updater's default


def simulation_status(array):
    for status in array.status:
        if "simulation" in status.name:
            return status
    return None


class DiagnosticsSimTimeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        support.start_client(cls, "diagnostics_sim_time_test")
        cls.diagnostics = support.TopicRecorder("/diagnostics", DiagnosticArray)
        cls.reset = rospy.ServiceProxy(NODE + "/reset", Empty)
        cls.set_paused = rospy.ServiceProxy(NODE + "/set_paused", SetBool)
        cls.reset.wait_for_service(timeout=10.0)

    def statuses(self, since):
        return [s for s in (simulation_status(m) for _, m in self.diagnostics.records(since)) if s]

    def test_1_diagnostics_go_on_after_a_reset(self):
        support.wait_until(lambda: self.states.latest().header.stamp.to_sec() > 3.0, 10.0)
        self.reset()
        after = time.monotonic()
        time.sleep(3.5)
        reports = self.statuses(after)
        self.assertGreaterEqual(len(reports), 3, "diagnostics silent after the reset")
        for status in reports:
            self.assertNotEqual(status.level, DiagnosticStatus.ERROR, status.message)
        self.assertLess(self.states.latest().header.stamp.to_sec(), 3.5 + 0.5)

    def test_2_back_to_back_resets_keep_the_state_rate(self):
        start = time.monotonic()
        while time.monotonic() - start < 2.0:
            self.reset()
        end = time.monotonic()
        states = [m for t, m in self.states.records(since=start) if t <= end]
        self.assertLessEqual(len(states), self.config["publish_rate"] * (end - start) + 2)
        self.assertGreaterEqual(len(self.statuses(start)), 1, "diagnostics silent during resets")
        time.sleep(0.5)
        self.assertTrue(support.state_is_finite(self.states.latest()))

    def test_3_pause_does_not_count_as_slow(self):
        self.set_paused(True)
        time.sleep(2.5)
        self.set_paused(False)
        resumed = time.monotonic()
        time.sleep(3.5)
        reports = self.statuses(resumed)
        self.assertGreaterEqual(len(reports), 3)
        for status in reports:
            self.assertNotIn("slower", status.message)


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "diagnostics_sim_time", DiagnosticsSimTimeTest)
