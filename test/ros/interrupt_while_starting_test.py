#!/usr/bin/python3
"""SIGINT and SIGTERM end yarn_tearing_node at once while it validates and builds a scene at the
scene budget (a quarter of a second to seconds of work that checks no ROS flag): exit status 128 + signal within
EXIT_WITHIN seconds, with one line on stderr. Once it steps, they end it within STEP_EXIT_WITHIN
seconds however long the step in progress takes (a large fabric started against a ball): status 0 when
the step ended in time, else 128 + signal with one line on stderr.

The config is uploaded to its own namespace per case, and the node binary is run directly with
__name:=<namespace>; the signal is sent once the node has registered with the master (so that
it is past ros::init) and 20 ms later, well before its build can be done."""
import os
import signal
import subprocess
import time
import unittest

import rosgraph
import rosparam
import roslib.packages
import rospy
import rostest

EXIT_WITHIN = 2.0      # [s] from the signal to the process's exit
STEP_EXIT_WITHIN = 1.0  # [s] from the signal to the exit of a node that is stepping
STEPPING_AFTER = 2.0    # [s] after registering: the small scene is built and stepping
REGISTER_WITHIN = 20.0  # [s] for the node to register with the master
AFTER_REGISTERING = 0.02  # [s] before the signal: past ros::init; the build (about 0.25 s on a 2.6 GHz
#                          Xeon, seconds on slower machines) is far from done


def wait_for_registration(name, timeout):
    master = rosgraph.Master("/interrupt_while_starting_test")
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            master.lookupNode("/" + name)
            return True
        except rosgraph.MasterError:
            time.sleep(0.02)
    return False


class InterruptWhileStartingTest(unittest.TestCase):
    def interrupt(self, name, sent, config, after, exit_within):
        """Starts the node on `config`, sends `sent` `after` [s] past its registration and waits
        `exit_within` [s] for it to end; returns (exit status, stderr, seconds it took)."""
        rosparam.upload_params("/" + name, self.materials)
        rosparam.upload_params("/" + name, config)
        node = subprocess.Popen([self.node_binary, "__name:=" + name], stderr=subprocess.PIPE,
                                stdout=subprocess.DEVNULL, text=True)
        try:
            self.assertTrue(wait_for_registration(name, REGISTER_WITHIN), "%s never registered" % name)
            time.sleep(after)
            self.assertIsNone(node.poll(), "%s was done before the signal" % name)
            node.send_signal(sent)
            start = time.monotonic()
            node.wait(timeout=exit_within)
            took = time.monotonic() - start
        finally:
            if node.poll() is None:
                node.kill()
                node.wait()
        rospy.loginfo("%s: exited %.3f s after signal %d", name, took, sent)
        return node.returncode, node.stderr.read(), took

    def setUp(self):
        rospy.init_node("interrupt_while_starting_test")
        self.node_binary = roslib.packages.find_node("yarn_tearing", "yarn_tearing_node")[0]
        self.materials = rosparam.load_file(rospy.get_param("~materials"))[0][0]

    def test_sigint_and_sigterm_end_the_build_at_once(self):
        config = rosparam.load_file(rospy.get_param("~config"))[0][0]
        for name, sent in (("interrupted_by_sigint", signal.SIGINT),
                           ("interrupted_by_sigterm", signal.SIGTERM)):
            status, stderr, _ = self.interrupt(name, sent, config, AFTER_REGISTERING, EXIT_WITHIN)
            self.assertEqual(status, 128 + sent, stderr)
            self.assertIn("interrupted while starting", stderr)

    def test_sigint_and_sigterm_end_a_long_step_within_a_second(self):
        config = rosparam.load_file(rospy.get_param("~stepping_config"))[0][0]
        for name, sent in (("stepping_sigint", signal.SIGINT),
                           ("stepping_sigterm", signal.SIGTERM)):
            status, stderr, took = self.interrupt(name, sent, config, STEPPING_AFTER,
                                                  STEP_EXIT_WITHIN + 5.0)
            self.assertLessEqual(took, STEP_EXIT_WITHIN, "%s took %.2f s to exit" % (name, took))
            self.assertIn(status, (0, 128 + sent), stderr)
            if status != 0:
                self.assertIn("outlasted the shutdown deadline", stderr)

if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "interrupt_while_starting", InterruptWhileStartingTest)
