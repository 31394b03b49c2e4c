#!/usr/bin/python3
"""Through topics only: yarn_states and yarn_markers are stamped in ROS time, so that a tf2
listener transforms a yarn_states position into a frame that moves relative to the fixed frame
(world -> base_link, broadcast here) at the message's stamp, and gets the position the motion
predicts; sim_time carries the simulated time."""
import time
import unittest

import rospy
import rostest
import tf2_ros
from visualization_msgs.msg import MarkerArray

import yarn_rostest_support as support

BASE_FRAME = "base_link"
SPEED = 0.2            # [m/s] base_link moves along world x
STAMP_NOW_WINDOW = 0.5  # [s] a stamp is this close to the ROS time it was received at
TOLERANCE = 1.0e-6     # [m] tf interpolates the linear motion exactly


class MovingBase:
    """Broadcasts world -> base_link at 100 Hz: x = SPEED * (t - start) in ROS time."""

    def __init__(self):
        self.start = rospy.Time.now().to_sec()
        self.frame = support.MovingFrame(BASE_FRAME, lambda stamp: (self.x(stamp.to_sec()), 0, 0))

    def x(self, stamp):
        return SPEED * (stamp - self.start)


class StampsInMovingFrameTest(unittest.TestCase):
    def test_positions_transform_at_their_stamp(self):
        rospy.init_node("stamps_in_moving_frame_test")
        yarn = support.load_yaml(rospy.get_param("~config"))["yarns"][0]
        buffer = tf2_ros.Buffer(rospy.Duration(10.0))
        tf2_ros.TransformListener(buffer)
        base = MovingBase()
        states = support.record_states()
        markers = support.TopicRecorder("yarn_markers", MarkerArray)
        self.assertTrue(states.wait_for_first(), "no yarn_states")
        time.sleep(1.0)  # tf history before the states we check

        checked = 0
        sim_times = []
        for msg in states.messages()[-20:]:
            stamp = msg.header.stamp
            lag = rospy.Time.now().to_sec() - stamp.to_sec()
            self.assertTrue(0.0 <= lag < 5.0, "stamp %.3f s is not recent ROS time" % stamp.to_sec())
            p = support.find_yarn(msg, yarn["name"]).positions[-1]
            # world -> base_link at the message's stamp (raises when tf cannot give it)
            transform = buffer.lookup_transform(BASE_FRAME, msg.header.frame_id, stamp,
                                                rospy.Duration(1.0)).transform
            self.assertAlmostEqual(transform.rotation.w, 1.0, delta=TOLERANCE)
            in_base_x = p.x + transform.translation.x  # the rotation is the identity
            self.assertAlmostEqual(in_base_x, p.x - base.x(stamp.to_sec()), delta=TOLERANCE)
            sim_times.append(msg.sim_time)
            checked += 1
        self.assertGreaterEqual(checked, 10)
        self.assertTrue(all(b > a for a, b in zip(sim_times, sim_times[1:])), "sim_time not rising")

        # A fresh state is stamped about now (real_time_factor 1: stamp = start + sim_time).
        received, latest = states.records()[-1]
        now_at_receipt = rospy.Time.now().to_sec() - (time.monotonic() - received)
        self.assertLess(abs(now_at_receipt - latest.header.stamp.to_sec()), STAMP_NOW_WINDOW)
        first = states.messages()[0]
        self.assertAlmostEqual(latest.header.stamp.to_sec() - first.header.stamp.to_sec(),
                               latest.sim_time - first.sim_time, delta=0.05)
        self.assertTrue(support.wait_until(lambda: markers.latest() is not None, timeout=5.0))
        self.assertGreater(markers.latest().markers[0].header.stamp.to_sec(), base.start - 60.0)
        base.frame.stop()


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "stamps_in_moving_frame", StampsInMovingFrameTest)
