#!/usr/bin/python3
"""Through topics only: a grasped vertex follows a moving tf frame (broadcast here with tf2_ros)
within a few mm, is reported as a support, and falls free again after release."""
import math
import time
import unittest

import rospy
import rostest
from yarn_tearing.msg import Grasp

import yarn_rostest_support as support

GRIPPER_FRAME = "gripper"
AMPLITUDE = 0.04     # [m]
PERIOD = 4.0         # [s]
CENTER = (0.0, 0.0, -0.15)  # [m], closer to the pin than the yarn is long: slack yarn
TOLERANCE = 0.003    # [m]
LAG_WINDOW = 0.1     # [s] the vertex may lag the frame by this much (tf + one cycle + topic)


class MovingGripper:
    """Broadcasts world -> gripper at 100 Hz moving on x = A sin(2 pi t / T) around CENTER."""

    def __init__(self):
        self.start = time.monotonic()
        self.frame = support.MovingFrame(GRIPPER_FRAME, lambda _: self.position(time.monotonic()))

    def position(self, wall_time):
        t = wall_time - self.start
        return (CENTER[0] + AMPLITUDE * math.sin(2.0 * math.pi * t / PERIOD), CENTER[1], CENTER[2])


class GraspTest(unittest.TestCase):
    def test_grasped_vertex_follows_frame(self):
        rospy.init_node("grasp_test")
        config = support.load_yaml(rospy.get_param("~config"))
        yarn = config["yarns"][0]
        last = yarn["num_vertices"] - 1
        states = support.record_states()
        self.assertTrue(states.wait_for_first(), "no yarn_states")
        gripper = MovingGripper()
        grasp_pub = rospy.Publisher("grasp", Grasp, queue_size=10)

        def grasped():
            state = states.latest()
            return last in support.find_yarn(state, yarn["name"]).support_vertices

        def send(release):
            msg = Grasp()
            msg.header.stamp = rospy.Time.now()
            msg.yarn, msg.vertex, msg.target_frame, msg.release = (yarn["name"], -1,
                                                                     GRIPPER_FRAME, release)
            grasp_pub.publish(msg)

        # Resend until accepted: the node refuses the grasp until it has the frame from tf.
        deadline = time.monotonic() + 10.0
        while not grasped() and time.monotonic() < deadline:
            send(release=False)
            time.sleep(0.2)
        self.assertTrue(grasped(), "grasp not accepted within 10 s")

        time.sleep(0.5)  # the vertex jumps to the frame in the first cycle
        start = time.monotonic()
        time.sleep(PERIOD * 0.75)
        records = states.records(since=start)
        self.assertGreater(len(records), 50)
        worst = 0.0
        for received, msg in records:
            p = support.find_yarn(msg, yarn["name"]).positions[last]
            distance = min(math.dist((p.x, p.y, p.z), gripper.position(received - lag))
                           for lag in [i * 0.005 for i in range(int(LAG_WINDOW / 0.005) + 1)])
            worst = max(worst, distance)
        self.assertLess(worst, TOLERANCE, "grasped vertex %.4f m from the frame" % worst)
        xs = [support.find_yarn(m, yarn["name"]).positions[last].x for _, m in records]
        self.assertGreater(max(xs) - min(xs), AMPLITUDE, "the vertex did not move with the frame")

        send(release=True)
        self.assertTrue(support.wait_until(lambda: not grasped(), timeout=5.0), "not released")
        self.assertEqual(list(support.find_yarn(states.latest(), yarn["name"]).support_vertices),
                         [0])
        gripper.frame.stop()


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "grasp", GraspTest)
