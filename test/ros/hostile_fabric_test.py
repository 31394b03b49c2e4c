#!/usr/bin/python3
"""Each hostile input of a client, sent to a node stepping a 16 x 12 cotton patch hanging from its
top row (test/ros/config/hostile_fabric.yaml): after each, the node is alive, fabric_states came at
their rate (within 20 %) without NaN through the input's window (3 s), and simulated time went on.
The inputs: an applied_force stamped 4294967295 s in a moving frame; a
force just within the bound (100 x its vertex's segments' breaking forces) on a corner, and one of
1e6 N; a grasp whose frame jumps 1e3 m every update; an attached obstacle whose frame jumps across
the patch every update; that obstacle's frame inside the torn patch; real_time_factor and
publish_rate NaN through dynamic_reconfigure; a seeded flood of 5,000 mixed valid and invalid
grasps and forces in 10 s (fabric_states at >= 80 % of their rate). Last, SIGINT ends the node
within 1 s. The node is started by the test, which sends the signal and reads the exit status."""
import math
import os
import random
import signal
import subprocess
import threading
import time
import unittest

import dynamic_reconfigure.client
import rosparam
import roslib.packages
import rospy
import rostest
import tf2_ros
import yaml
from geometry_msgs.msg import TransformStamped, Vector3
from std_msgs.msg import String
from yarn_tearing.msg import AppliedForce, FabricStateArray, Grasp

import yarn_rostest_support as support

NODE = "yarn_tearing"
FABRIC = "cloth"
RATE_TOLERANCE = 0.20    # fabric_states' rate through each input's window
FLOOD_RATE_SHARE = 0.80  # fabric_states' rate through the flood, at least this share
WINDOW = 3.0             # [s] an input is sent through this much wall time
FLOOD_MESSAGES = 5000
FLOOD_SECONDS = 10.0
SEED = 7
EXIT_WITHIN = 1.0        # [s] from SIGINT to the node's exit
LAST_STAMP = rospy.Time(4294967295)
NAN = float("nan")


def transform(child, xyz, stamp):
    t = TransformStamped()
    t.header.stamp, t.header.frame_id, t.child_frame_id = stamp, "world", child
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = xyz
    t.transform.rotation.w = 1.0
    return t


class Frames:
    """Broadcasts each frame of `positions` (name -> callable of the tick giving xyz) at 50 Hz."""

    def __init__(self):
        self.broadcaster = tf2_ros.TransformBroadcaster()
        self.positions = {}
        self.lock = threading.Lock()
        threading.Thread(target=self.run, daemon=True).start()

    def set(self, name, position):
        with self.lock:
            self.positions[name] = position

    def run(self):
        tick = 0
        while not rospy.is_shutdown():
            now = rospy.Time.now()
            with self.lock:
                frames = [transform(n, p(tick), now) for n, p in self.positions.items()]
            if frames:
                self.broadcaster.sendTransform(frames)
            tick += 1
            time.sleep(0.02)


class HostileFabricTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("hostile_fabric_test")
        cls.config = support.load_yaml(rospy.get_param("~config"))
        materials = rosparam.load_file(rospy.get_param("~materials"))[0][0]
        rosparam.upload_params("/" + NODE, materials)
        rosparam.upload_params("/" + NODE, cls.config)
        binary = roslib.packages.find_node("yarn_tearing", "yarn_tearing_node")[0]
        cls.node = subprocess.Popen([binary, "__name:=" + NODE], stdout=subprocess.DEVNULL,
                                    stderr=subprocess.PIPE, text=True)
        cls.states = support.TopicRecorder("fabric_states", FabricStateArray)
        cls.breaks = support.record_breaks()
        cls.force_pub = rospy.Publisher("applied_force", AppliedForce, queue_size=1000)
        cls.grasp_pub = rospy.Publisher("grasp", Grasp, queue_size=1000)
        cls.frames = Frames()
        cls.frames.set("moving_frame", lambda tick: (0.0, 0.0, -0.03))
        cls.started = time.monotonic()
        assert cls.states.wait_for_first(30.0), "no fabric_states within 30 s"
        cls.materials = yaml.safe_load(
            rospy.wait_for_message("yarn_materials", String, timeout=5.0).data)
        time.sleep(0.5)  # the publishers and tf connect

    @classmethod
    def tearDownClass(cls):
        if cls.node.poll() is None:
            cls.node.kill()
            cls.node.wait()

    def force(self, vertex, f, frame="", stamp=rospy.Time(0), yarn=FABRIC, duration=0.0):
        msg = AppliedForce()
        msg.header.frame_id, msg.header.stamp = frame, stamp
        msg.yarn, msg.vertex, msg.force, msg.duration = yarn, vertex, Vector3(*f), duration
        self.force_pub.publish(msg)

    def grasp(self, vertex, frame, release=False, yarn=FABRIC):
        msg = Grasp()
        msg.yarn, msg.vertex, msg.target_frame, msg.release = yarn, vertex, frame, release
        self.grasp_pub.publish(msg)

    def check_window(self, start, end, what, share=None):
        """Alive; fabric_states at their rate (within RATE_TOLERANCE, or >= share of it) from
        `start` to `end` without NaN; simulated time went on."""
        self.assertIsNone(self.node.poll(), "the node ended during %s: %s" %
                          (what, self.node.stderr.read() if self.node.poll() is not None else ""))
        records = [(t, m) for t, m in self.states.records(since=start) if t <= end]
        rate = support.measured_rate(records)
        expected = self.config["publish_rate"]
        rospy.loginfo("%s: fabric_states at %.2f Hz (%d), simulated %.3f s in %.2f s", what, rate,
                      len(records), records[-1][1].sim_time - records[0][1].sim_time
                      if records else 0.0, end - start)
        if share is None:
            self.assertLess(abs(rate - expected) / expected, RATE_TOLERANCE,
                            "%s: fabric_states at %.2f Hz, expected %.1f" % (what, rate, expected))
        else:
            self.assertGreaterEqual(rate, share * expected,
                                    "%s: fabric_states at %.2f Hz, expected %.1f" %
                                    (what, rate, expected))
        for _, states in records:
            self.assertTrue(support.fabric_state_is_finite(states),
                            "%s: NaN or inf in fabric_states" % what)
        self.assertGreater(records[-1][1].sim_time, records[0][1].sim_time,
                           "%s: simulated time stood still" % what)

    def during(self, what, send, seconds=WINDOW, share=None):
        start = time.monotonic()
        while time.monotonic() < start + seconds:
            send()
            time.sleep(0.05)
        self.check_window(start, time.monotonic(), what, share)

    def vertex(self, row, column):
        return row * self.config["fabrics"][0]["ends"] + column

    def corner_strength(self):
        """[N] the breaking forces of the last row's last vertex's two segments, summed."""
        return sum(self.materials["%s/%s" % (FABRIC, family)]["breaking_stress"] *
                   self.materials["%s/%s" % (FABRIC, family)]["area"]
                   for family in ("warp", "weft"))

    def test_1_at_rest(self):
        start = self.states.records()[0][0]
        time.sleep(max(0.0, start + WINDOW - time.monotonic()))
        rospy.loginfo("first fabric_states %.2f s after the node's start",
                      start - self.started)
        self.check_window(start, time.monotonic(), "the patch at rest")

    def test_2_stamp_at_the_end_of_ros_time(self):
        self.during("a force stamped 4294967295 s in a moving frame",
                    lambda: self.force(-1, (0.0, 0.01, 0.0), "moving_frame", LAST_STAMP))

    def test_3_forces_at_and_past_the_bound(self):
        bound = 100.0 * self.corner_strength()
        self.during("a force of 0.99 x the bound on a corner",
                    lambda: self.force(-1, (0.0, 0.99 * bound, 0.0), duration=0.02))
        self.during("a force of 1e6 N on a corner", lambda: self.force(-16, (0.0, 1.0e6, 0.0)))
        self.force(-16, (0.0, 0.0, 0.0))

    def test_4_grasp_frame_jumping_a_kilometre(self):
        self.frames.set("jump_frame", lambda tick: (1.0e3 * (tick % 2), 0.0, -0.03))
        time.sleep(0.2)
        self.during("a grasp whose frame jumps 1e3 m every update",
                    lambda: self.grasp(self.vertex(6, 3), "jump_frame"))
        self.grasp(self.vertex(6, 3), "", release=True)

    def test_5_obstacle_jumping_across_the_patch(self):
        self.frames.set("finger_frame", lambda tick: (0.02, 0.02 * (-1) ** tick, -0.02))
        self.during("an obstacle whose frame jumps across the patch every update", lambda: None)

    def test_6_obstacle_frame_inside_the_torn_patch(self):
        # tear the lower half's corner region off with forces within the bound, then put the
        # finger where the patch was
        bound = 100.0 * self.corner_strength()
        for row, column in ((11, 15), (10, 15), (11, 14), (10, 14)):
            self.force(self.vertex(row, column), (0.0, 0.5 * bound, 0.0), duration=0.05)
        time.sleep(0.5)
        torn = sum(self.states.latest().fabrics[0].broken)
        rospy.loginfo("%d segments torn before the finger comes", torn)
        self.assertGreater(torn, 0, "the patch did not tear")
        self.frames.set("finger_frame", lambda tick: (0.035, 0.0, -0.055 + 0.002 * (tick % 2)))
        self.during("an obstacle frame inside the torn patch", lambda: None)
        self.frames.set("finger_frame", lambda tick: (0.2, 0.2, 0.2))

    def test_7_nan_through_live_tuning(self):
        client = dynamic_reconfigure.client.Client("/" + NODE, timeout=10.0)
        start = time.monotonic()
        for name in ("real_time_factor", "publish_rate"):
            config = client.update_configuration({name: NAN})
            self.assertEqual(config[name], self.config[name], "%s NaN taken" % name)
        time.sleep(WINDOW)
        self.check_window(start, time.monotonic(), "real_time_factor and publish_rate NaN")

    def flood_message(self, rng):
        """A grasp or force, valid or not (vertex, frame, number), from `rng`."""
        vertex = rng.choice([rng.randrange(16 * 12), -1, 1000, -1000, 2 ** 31 - 1])
        frame = rng.choice(["world", "moving_frame", "jump_frame", "no_frame", "", "x" * 300])
        yarn = rng.choice([FABRIC, FABRIC, FABRIC, "nothing", "cloth/warp"])
        if rng.random() < 0.5:
            f = tuple(rng.choice([rng.uniform(-0.2, 0.2), NAN, 1.0e308, 1.0e6])
                      if rng.random() < 0.1 else rng.uniform(-0.2, 0.2) for _ in range(3))
            self.force(vertex, f, rng.choice(["", "", "world", "no_frame"]),
                       LAST_STAMP if rng.random() < 0.02 else rospy.Time(0), yarn,
                       rng.choice([0.0, 0.05, 0.5]))
        else:
            self.grasp(vertex, frame, rng.random() < 0.3, yarn)

    def test_8_seeded_flood(self):
        rng = random.Random(SEED)
        start = time.monotonic()
        for i in range(FLOOD_MESSAGES):
            self.flood_message(rng)
            if i % 25 == 24:
                time.sleep(max(0.0, start + (i + 1) * FLOOD_SECONDS / FLOOD_MESSAGES -
                               time.monotonic()))
        self.check_window(start, time.monotonic(), "a flood of %d grasps and forces" %
                          FLOOD_MESSAGES, share=FLOOD_RATE_SHARE)
        for event in self.breaks.messages():
            material = self.materials[event.yarn]
            self.assertTrue(math.isfinite(event.tension), event)
            self.assertLessEqual(event.strain, material["breaking_strain"] * (1.0 + 1.0e-9))

    def test_9_sigint_ends_the_node_within_a_second(self):
        self.node.send_signal(signal.SIGINT)
        start = time.monotonic()
        self.node.wait(timeout=EXIT_WITHIN + 5.0)
        took = time.monotonic() - start
        rospy.loginfo("the node exited %.3f s after SIGINT with %d", took, self.node.returncode)
        self.assertLessEqual(took, EXIT_WITHIN)
        self.assertIn(self.node.returncode, (0, 128 + signal.SIGINT))


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "hostile_fabric", HostileFabricTest)
