#!/usr/bin/python3
"""plot_bag on a bag recorded in a test run. yarn_states, break_events and the latched
yarn_materials are written into a rosbag as they arrive, until AFTER_BREAK simulated seconds
after the tear; yarn_plotting.make_all (from the package's scripts folder, as test/plot imports
it) then writes each figure, and the break instants it draws are the bag's BreakEvent stamps."""
import os
import shutil
import sys
import tempfile
import threading
import unittest

import rosbag
import rospy
import rostest
from std_msgs.msg import String
from yarn_tearing.msg import BreakEvent, YarnStateArray

import yarn_rostest_support as support

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..",
                                "scripts"))
from yarn_plotting import FIGURES, make_all  # noqa: E402

AFTER_BREAK = 0.5  # [s] simulated time of yarn_states recorded after the break
TIMEOUT = 15.0     # [s] wall time for the tear and the states after it


class BagRecorder:
    """Writes every yarn_states, break_events and yarn_materials message into `bag` on arrival."""

    TOPICS = (("yarn_states", YarnStateArray), ("break_events", BreakEvent),
              ("yarn_materials", String))

    def __init__(self, bag):
        self.bag = bag
        self.lock = threading.Lock()
        self.counts = {name: 0 for name, _ in self.TOPICS}
        self.breaks = []
        self.first_state = self.last_state = None  # [s] header.stamp
        self.subscribers = [
            rospy.Subscriber(name, cls, self.write, callback_args=name, queue_size=10000)
            for name, cls in self.TOPICS]

    def write(self, msg, name):
        with self.lock:
            if self.bag is None:
                return
            self.bag.write(rospy.resolve_name(name), msg)
            self.counts[name] += 1
            if name == "break_events":
                self.breaks.append(msg)
            elif name == "yarn_states":
                stamp = msg.header.stamp.to_sec()
                self.first_state = stamp if self.first_state is None else self.first_state
                self.last_state = stamp

    def done(self):
        """The materials, a break and AFTER_BREAK seconds of states after it are in the bag."""
        with self.lock:
            return bool(self.counts["yarn_materials"] and self.breaks and self.last_state
                        >= self.breaks[0].header.stamp.to_sec() + AFTER_BREAK)

    def stop(self):
        with self.lock:
            for subscriber in self.subscribers:
                subscriber.unregister()
            self.bag = None


class PlotRecordedBagTest(unittest.TestCase):
    def test_figures_of_a_recorded_bag(self):
        rospy.init_node("plot_recorded_bag_test")
        tmp = tempfile.mkdtemp(prefix="plot_recorded_bag_")
        self.addCleanup(shutil.rmtree, tmp, True)
        path = os.path.join(tmp, "recorded.bag")
        with rosbag.Bag(path, "w") as bag:
            recorder = BagRecorder(bag)
            recorded = support.wait_until(recorder.done, timeout=TIMEOUT)
            recorder.stop()
        self.assertTrue(recorded, "recorded %s" % recorder.counts)
        stamps = [event.header.stamp.to_sec() for event in recorder.breaks]
        self.assertLess(recorder.first_state, stamps[0], "no states before the tear recorded")

        result = make_all(path, os.path.join(tmp, "figures"))
        self.assertEqual(sorted(result["paths"]), sorted(FIGURES))
        for name, figure in result["paths"].items():
            self.assertTrue(os.path.isfile(figure), name)
            self.assertGreater(os.path.getsize(figure), 0, name)
        drawn = sorted(t + result["time_origin"] for t in result["break_times"])
        self.assertEqual(len(drawn), len(stamps))
        for t_drawn, t_bag in zip(drawn, sorted(stamps)):
            self.assertAlmostEqual(t_drawn, t_bag, delta=1.0e-9)
        self.assertEqual(result["strengths"]["specimen"].source, "bag metadata")


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "plot_recorded_bag", PlotRecordedBagTest)
