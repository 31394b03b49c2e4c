#!/usr/bin/python3
"""While one step runs for seconds (a 128 x 96 patch started against a ball,
test/ros/config/fabric_pressing_ball.yaml), the node's services answer, /diagnostics goes on
saying how long the step has run, and fabric_states are re-sent at their rate with the last
state's sim_time (the initial state during the first step). A ~reset asked during the step is applied when it ends: ~get_break_events
answers as after the reset at once, and the next states start again from simulated time 0."""
import threading
import time
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from std_srvs.srv import Empty, SetBool
from yarn_tearing.msg import FabricStateArray
from yarn_tearing.srv import GetBreakEvents

import yarn_rostest_support as support

NODE = "/yarn_tearing"
ANSWER_WITHIN = 0.5     # [s] wall: a service's answer during a long step
LONG_STEP = 0.5         # [s] wall: a step that has run this long is under way
RATE_SHARE = 0.8        # fabric_states' rate during the step, at least this share
WATCH = 3.0             # [s] wall watched during the step


def in_progress(diagnostics):
    """The 'step in progress [s]' of the node's report, or None."""
    for status in diagnostics.status:
        for value in status.values:
            if value.key == "step in progress [s]":
                return float(value.value)
    return None


def timed_call(proxy, *args):
    """(answer, seconds) of a service call, waiting at most 10 s."""
    result = {}

    def call():
        result["answer"] = proxy(*args)
    start = time.monotonic()
    thread = threading.Thread(target=call, daemon=True)
    thread.start()
    thread.join(10.0)
    return result.get("answer"), time.monotonic() - start


class LongStepServicesTest(unittest.TestCase):
    def test_services_diagnostics_and_states_during_a_long_step(self):
        rospy.init_node("long_step_services_test")
        rate = rospy.get_param(NODE + "/publish_rate")
        diagnostics = support.TopicRecorder("/diagnostics", DiagnosticArray)
        states = support.TopicRecorder("fabric_states", FabricStateArray)
        for name in ("reset", "set_paused", "get_break_events"):
            rospy.wait_for_service(NODE + "/" + name, timeout=60.0)
        long_step = support.wait_until(
            lambda: any((in_progress(m) or 0.0) >= LONG_STEP for m in diagnostics.messages()),
            60.0)
        self.assertTrue(long_step, "no step ran for %.1f s" % LONG_STEP)

        events, took = timed_call(rospy.ServiceProxy(NODE + "/get_break_events", GetBreakEvents), 0)
        self.assertIsNotNone(events)
        self.assertLess(took, ANSWER_WITHIN, "get_break_events took %.2f s" % took)
        for paused in (True, False):
            answer, took = timed_call(rospy.ServiceProxy(NODE + "/set_paused", SetBool), paused)
            self.assertTrue(answer.success)
            self.assertLess(took, ANSWER_WITHIN, "set_paused took %.2f s" % took)
        reset_called = time.monotonic()
        _, took = timed_call(rospy.ServiceProxy(NODE + "/reset", Empty))
        self.assertLess(took, ANSWER_WITHIN, "reset took %.2f s" % took)
        events, took = timed_call(rospy.ServiceProxy(NODE + "/get_break_events", GetBreakEvents), 0)
        self.assertEqual((events.total, len(events.events)), (0, 0))
        self.assertLess(took, ANSWER_WITHIN, "get_break_events took %.2f s" % took)
        initial = [m for t, m in states.records() if t < reset_called and m.sim_time == 0.0]
        self.assertGreaterEqual(len(initial), 2, "the initial state was not re-sent")

        # The reset comes when the step ends; the patch starts against the ball again and its
        # steps are as long: the states published between them are re-sent during them.
        self.assertTrue(states.wait_for_first(60.0), "no fabric_states")
        first_state = states.records()[0][0]
        long_again = support.wait_until(
            lambda: any((in_progress(m) or 0.0) >= LONG_STEP
                        for t, m in diagnostics.records(since=first_state)), 60.0)
        self.assertTrue(long_again, "no long step after the first state")
        start = time.monotonic()
        time.sleep(WATCH)
        watched = [m.sim_time for t, m in states.records(since=start)]
        reports = [in_progress(m) for t, m in diagnostics.records(since=start)]
        rospy.loginfo("during the step: %d fabric_states (sim_time %r), step in progress %r",
                      len(watched), sorted(set(watched)), reports)
        self.assertGreaterEqual(len(watched), RATE_SHARE * rate * WATCH)
        self.assertGreater(len(watched), len(set(watched)), "no state was re-sent")
        self.assertTrue(all(t < 0.1 for t in watched), "states from before the reset")
        self.assertTrue(any(r and r > LONG_STEP for r in reports), reports)

if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "long_step_services", LongStepServicesTest)
