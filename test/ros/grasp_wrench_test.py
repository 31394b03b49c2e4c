#!/usr/bin/python3
"""Through topics only: the wrench a hanging yarn exerts on its holder is its weight m g, with
m = density * pi r^2 * length from this test's own config: on the pin in the fixed frame
(~pin_wrench/<yarn>/vertex_0), then on a gripper rotated 90 degrees about x that grasps the same
vertex, rotated into the gripper's frame (~grasp_wrench/<yarn>/vertex_0): (0, -m g, 0)."""
import math
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import WrenchStamped
from yarn_tearing.msg import Grasp

import yarn_rostest_support as support

GRIPPER_FRAME = "gripper"
TOLERANCE = 0.01  # of the weight: the settled yarn's holder carries it (0.5 % in the core tests)


class GraspWrenchTest(unittest.TestCase):
    def assert_force(self, wrench, expected, weight):
        force = wrench.wrench.force
        for got, want, axis in zip((force.x, force.y, force.z), expected, "xyz"):
            self.assertLess(abs(got - want), TOLERANCE * weight,
                            "force.%s = %.4g N, expected %.4g N" % (axis, got, want))
        torque = wrench.wrench.torque
        self.assertEqual((torque.x, torque.y, torque.z), (0.0, 0.0, 0.0))

    def test_holder_reads_the_weight(self):
        rospy.init_node("grasp_wrench_test")
        config = support.load_yaml(rospy.get_param("~config"))
        yarn = config["yarns"][0]
        mass = yarn["material"]["density"] * math.pi * yarn["radius"] ** 2 * yarn["length"]
        weight = mass * -config["gravity"][2]  # [N]
        topic = "/yarn_tearing/%s_wrench/%s/vertex_0"

        pin = support.TopicRecorder(topic % ("pin", yarn["name"]), WrenchStamped)
        self.assertTrue(pin.wait_for_first(), "no pin wrench")
        time.sleep(1.0)  # settled
        self.assertEqual(pin.latest().header.frame_id, config["frame_id"])
        self.assert_force(pin.latest(), (0.0, 0.0, -weight), weight)

        gripper = support.TopicRecorder(topic % ("grasp", yarn["name"]), WrenchStamped)
        grasp_pub = rospy.Publisher("grasp", Grasp, queue_size=10)
        deadline = time.monotonic() + 10.0
        while gripper.latest() is None and time.monotonic() < deadline:
            grasp_pub.publish(Grasp(yarn=yarn["name"], vertex=0, target_frame=GRIPPER_FRAME))
            time.sleep(0.2)
        self.assertIsNotNone(gripper.latest(), "no grasp wrench within 10 s")
        time.sleep(0.5)
        wrench = gripper.latest()
        self.assertEqual(wrench.header.frame_id, GRIPPER_FRAME)
        # gripper = world rotated +90 deg about x: world -z is the gripper's -y
        self.assert_force(wrench, (0.0, -weight, 0.0), weight)
        self.assertLess(abs(rospy.Time.now().to_sec() - wrench.header.stamp.to_sec()), 5.0)


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "grasp_wrench", GraspWrenchTest)
