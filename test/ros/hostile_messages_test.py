#!/usr/bin/python3
"""Through topics only: nothing a client sends can kill, poison or stall the node.

1. A flood of 10,000 distinct bad messages in 10 s (out-of-range vertices, unknown yarns, 200 kB
   names, forces past 1e6 N, infinities, unknown, stale, infinite and 1e308 tf frames): at most
   one warning per reason per 2 s, yarn_states keep their rate without NaN, RSS grows < 5 MB.
2. A seeded fuzz of 3,000 mutated applied_force / grasp messages (valid ones too, so yarns tear
   and grasps jump): the node stays alive, states keep their rate without NaN, every break event
   is within its yarn's breaking point, RSS grows < 5 MB.
3. A grasp whose frame stops being updated is reported once and holds its last target; a new
   grasp to the stale frame is refused.
4. Stamps at the end of ROS time (4294967295 s): an applied_force and a grasp's velocity in a
   non-static frame at that stamp are refused, a tf sample of a non-static frame at it is refused
   (tf2's cache arithmetic would leave ROS time's range), with a warning naming the reason; a grasp
   on that frame is refused; the node keeps stepping.
5. A force past 100 x the breaking forces of its vertex's segments is refused, naming the bound."""
import math
import random
import re
import threading
import time
import unittest
import xmlrpc.client

import rosgraph
import rospy
import rostest
import tf2_ros
import yaml
from geometry_msgs.msg import TransformStamped, Vector3
from rosgraph_msgs.msg import Log
from std_msgs.msg import String
from std_srvs.srv import Empty
from yarn_tearing.msg import AppliedForce, Grasp

import yarn_rostest_support as support

NODE = "/yarn_tearing"
SEED = 10
WARN_PERIOD = 2.0         # [s] the node's throttle period per reason
RATE_TOLERANCE = 0.10
RSS_GROWTH_LIMIT = 5.0 * 1024  # [kB]
FLOOD_MESSAGES = 10000
FLOOD_SECONDS = 10.0
FUZZ_MESSAGES = 3000
FUZZ_SECONDS = 6.0
HUGE = 200000             # [characters] of a huge name
NAN, INF = float("nan"), float("inf")


def node_pid():
    master = rosgraph.Master(rospy.get_name())
    uri = master.lookupNode(NODE)
    return xmlrpc.client.ServerProxy(uri).getPid(rospy.get_name())[2]


def rss_kb(pid):
    with open("/proc/%d/status" % pid) as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return float(line.split()[1])
    raise RuntimeError("no VmRSS for pid %d" % pid)


def send_paced(send, count, seconds):
    """Calls send(i) for i < count, evenly over `seconds`; returns the (start, end) wall times."""
    start = time.monotonic()
    for i in range(count):
        send(i)
        if i % 25 == 24:
            time.sleep(max(0.0, start + (i + 1) * seconds / count - time.monotonic()))
    return start, time.monotonic()


def transform(child, xyz, stamp):
    t = TransformStamped()
    t.header.stamp = stamp
    t.header.frame_id = "world"
    t.child_frame_id = child
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = xyz
    t.transform.rotation.w = 1.0
    return t


class Frames:
    """Static frames far (1e308 m), infinite and ok; stale_frame re-sent 5 s old; moving_frame
    sent at 50 Hz while `moving` is set."""

    def __init__(self):
        self.static = tf2_ros.StaticTransformBroadcaster()
        now = rospy.Time.now()
        self.static.sendTransform([transform("far_frame", (1.0e308, 0.0, 0.0), now),
                                   transform("inf_frame", (INF, 0.0, 0.0), now),
                                   transform("ok_frame", (0.05, 0.0, -0.1), now)])
        self.broadcaster = tf2_ros.TransformBroadcaster()
        self.moving = threading.Event()
        self.moving_position = (0.0, 0.0, -0.15)
        threading.Thread(target=self.run, daemon=True).start()

    def run(self):
        tick = 0
        while not rospy.is_shutdown():
            now = rospy.Time.now()
            if tick % 10 == 0:
                self.broadcaster.sendTransform(
                    transform("stale_frame", (0.0, 0.0, -0.1), now - rospy.Duration(5.0)))
            if self.moving.is_set():
                self.broadcaster.sendTransform(transform("moving_frame", self.moving_position, now))
            tick += 1
            time.sleep(0.02)


class LogRecorder(support.TopicRecorder):
    """The node's log messages on /rosout."""

    def __init__(self):
        super().__init__("/rosout", Log)

    def texts(self, since, level=Log.WARN):
        return [m.msg for t, m in self.records(since) if m.name == NODE and m.level == level]


def warning_key(text):
    """(source, reason) of one of the node's refusal warnings, or None."""
    match = re.match(r"^(applied_force|grasp) refused \(([^,]+),", text)
    if match:
        return match.groups()
    match = re.match(r"^grasp of .* keeps its last target \(([^;]+);", text)
    return ("grasp target", match.group(1)) if match else None


class HostileMessagesTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        support.start_client(cls, "hostile_messages_test")
        cls.logs = LogRecorder()
        cls.breaks = support.record_breaks()
        cls.force_pub = rospy.Publisher("applied_force", AppliedForce, queue_size=1000)
        cls.grasp_pub = rospy.Publisher("grasp", Grasp, queue_size=1000)
        cls.frames = Frames()
        materials = rospy.wait_for_message("yarn_materials", String, timeout=5.0)
        cls.materials = yaml.safe_load(materials.data)
        cls.pid = node_pid()
        time.sleep(1.5)  # the yarns settle; stale_frame is old

    def force(self, yarn="a", vertex=-1, f=(0.0, 0.0, -0.01), frame="", duration=0.0,
              stamp=rospy.Time(0)):
        msg = AppliedForce()
        msg.header.frame_id, msg.header.stamp = frame, stamp
        msg.yarn, msg.vertex, msg.force, msg.duration = yarn, vertex, Vector3(*f), duration
        self.force_pub.publish(msg)

    def grasp(self, yarn="a", vertex=-1, frame="world", release=False, velocity=(0.0, 0.0, 0.0),
              velocity_frame="", stamp=rospy.Time(0)):
        msg = Grasp()
        msg.yarn, msg.vertex, msg.target_frame, msg.release = yarn, vertex, frame, release
        msg.header.frame_id, msg.header.stamp = velocity_frame, stamp
        msg.velocity = Vector3(*velocity)
        self.grasp_pub.publish(msg)

    def check_states(self, start, end):
        records = [(t, m) for t, m in self.states.records(since=start) if t <= end]
        rate = support.measured_rate(records)
        expected = self.config["publish_rate"]
        self.assertLess(abs(rate - expected) / expected, RATE_TOLERANCE,
                        "yarn_states at %.2f Hz, expected %.1f Hz" % (rate, expected))
        for _, states in records:
            self.assertTrue(support.state_is_finite(states), "NaN or inf in yarn_states")

    def check_warnings_throttled(self, start, end):
        periods = math.ceil((end - start) / WARN_PERIOD) + 1
        counts = {}
        for text in self.logs.texts(since=start):
            key = warning_key(text)
            if key is not None:
                counts[key] = counts.get(key, 0) + 1
        self.assertTrue(counts, "no refusal warning at all")
        for key, count in counts.items():
            self.assertLessEqual(count, periods, "%r warned %d times in %.1f s" %
                                 (key, count, end - start))
        return counts

    def bad_message(self, i):
        kind = i % 10
        if kind == 0:
            self.force(vertex=1000 + i)
        elif kind == 1:
            self.force(yarn="no_yarn_%d" % i)
        elif kind == 2:
            self.force(f=(1.0e7 + i, 0.0, 0.0))
        elif kind == 3:
            self.force(f=(INF, NAN, float(i)))
        elif kind == 4:
            self.force(frame="no_frame_%d" % i)
        elif kind == 5:
            self.grasp(vertex=i % 11, frame="far_frame")
        elif kind == 6:
            self.grasp(yarn="b", vertex=i % 11, frame="stale_frame")
        elif kind == 7:
            self.grasp(vertex=i % 11, release=True)
        elif kind == 8:
            self.force(yarn=("y" * HUGE + str(i)) if i % 100 == 8 else "a", duration=-1.0 - i)
        else:
            self.grasp(vertex=-(i % 11) - 1, frame="inf_frame")

    def test_1_flood_of_distinct_bad_messages(self):
        rss_before = rss_kb(self.pid)
        start, end = send_paced(self.bad_message, FLOOD_MESSAGES, FLOOD_SECONDS)
        time.sleep(0.5)
        self.check_states(start, end)
        counts = self.check_warnings_throttled(start, end + 0.5)
        self.assertGreaterEqual(len(counts), 7, "reasons warned: %r" % counts)
        growth = rss_kb(self.pid) - rss_before
        self.assertLess(growth, RSS_GROWTH_LIMIT, "RSS grew by %.0f kB" % growth)
        yarn = support.find_yarn(self.states.latest(), "a")
        self.assertAlmostEqual(yarn.positions[-1].z, -0.2, delta=2.0e-3)  # nothing moved it

    def mutated_message(self, rng):
        numbers = [NAN, INF, -INF, 1.0e308, -1.0e308, 1.0e300, 1.0e7, 1.0e6, 5.0e5, 0.0, -0.0,
                   5.0e-324, 1.0e-300]
        names = ["a", "b", "", "c", "a" * 300, "x" * HUGE, "\u00ff", "a\x00b"]
        frames = ["world", "ok_frame", "far_frame", "inf_frame", "stale_frame", "", "no_frame",
                  "/world", "f" * HUGE]
        vertices = [-2 ** 31, 2 ** 31 - 1, -12, -11, 11, 1000]

        def number(usual):
            return rng.choice(numbers) if rng.random() < 0.3 else usual

        yarn = rng.choice(names) if rng.random() < 0.2 else rng.choice(["a", "b"])
        vertex = rng.choice(vertices) if rng.random() < 0.2 else rng.randint(-11, 10)
        if rng.random() < 0.6:
            f = tuple(number(rng.uniform(-0.5, 0.5)) for _ in range(3))
            frame = rng.choice(frames) if rng.random() < 0.2 else ""
            stamp = rospy.Time(rng.randint(1, 2 ** 31 - 1)) if rng.random() < 0.05 else rospy.Time(0)
            duration = number(rng.choice([0.0, 0.05, 0.5]))
            self.force(yarn, vertex, f, frame, duration, stamp)
        else:
            frame = rng.choice(frames) if rng.random() < 0.5 else rng.choice(["world", "ok_frame"])
            self.grasp(yarn, vertex, frame, rng.random() < 0.3)

    def test_2_seeded_fuzz(self):
        rng = random.Random(SEED)
        rss_before = rss_kb(self.pid)
        start, end = send_paced(lambda i: self.mutated_message(rng), FUZZ_MESSAGES, FUZZ_SECONDS)
        time.sleep(0.5)
        self.assertEqual(node_pid(), self.pid, "the node restarted or died")
        self.check_states(start, end + 0.5)
        growth = rss_kb(self.pid) - rss_before
        self.assertLess(growth, RSS_GROWTH_LIMIT, "RSS grew by %.0f kB" % growth)
        for event in self.breaks.messages():
            material = self.materials[event.yarn]
            for value in (event.tension, event.stress, event.strain, event.plastic_strain,
                          event.strain_rate):
                self.assertTrue(math.isfinite(value), "non-finite break event %s" % event)
            self.assertLessEqual(event.strain, material["breaking_strain"] * (1.0 + 1.0e-9))
            self.assertLessEqual(event.stress, material["breaking_stress"] * (1.0 + 1.0e-9))
        rospy.ServiceProxy(NODE + "/reset", Empty)()

    def test_3_stale_grasp_frame_reported_once_and_held(self):
        self.frames.moving.set()
        time.sleep(0.5)
        self.grasp("a", -1, "moving_frame")
        time.sleep(1.0)
        yarn = support.find_yarn(self.states.latest(), "a")
        self.assertIn(10, list(yarn.support_vertices))
        stopped = time.monotonic()
        self.frames.moving.clear()
        time.sleep(3.5)
        reports = [t for t in self.logs.texts(since=stopped) if "holds its last target" in t]
        self.assertEqual(len(reports), 1, "stale-frame reports: %r" % reports)
        self.assertIn("moving_frame", reports[0])
        yarn = support.find_yarn(self.states.latest(), "a")
        self.assertIn(10, list(yarn.support_vertices), "the grasp was released")
        end = yarn.positions[10]
        self.assertLess(math.dist((end.x, end.y, end.z), self.frames.moving_position), 1.0e-3)
        refused_since = time.monotonic()
        self.grasp("b", -1, "moving_frame")
        time.sleep(0.5)
        self.assertTrue(any("stale frame" in t for t in self.logs.texts(since=refused_since)),
                        "a new grasp to the stale frame was not refused")

    def test_4_stamp_at_the_end_of_ros_time(self):
        self.frames.moving.set()
        time.sleep(0.5)
        last = rospy.Time(4294967295)  # the largest stamp ROS time has
        since = time.monotonic()
        broadcaster = tf2_ros.TransformBroadcaster()
        time.sleep(0.5)  # the node subscribes to the new broadcaster
        broadcaster.sendTransform(transform("last_frame", (0.0, 0.0, -0.2), last))
        time.sleep(0.2)
        for _ in range(3):
            self.force("b", -1, (0.0, 0.0, -0.01), "moving_frame", 0.0, last)
            self.grasp("b", 3, "ok_frame", velocity=(0.01, 0.0, 0.0),
                       velocity_frame="moving_frame", stamp=last)
            time.sleep(0.1)
        self.grasp("a", 4, "last_frame")
        time.sleep(1.5)
        self.assertEqual(node_pid(), self.pid, "the node restarted or died")
        self.check_states(since + 0.5, time.monotonic())
        texts = self.logs.texts(since=since)
        for topic in ("applied_force", "grasp"):
            refusals = [t for t in texts if t.startswith(topic + " refused") and
                        "moving_frame" in t]
            self.assertTrue(refusals, "%s at stamp %d s not refused: %r" %
                            (topic, last.secs, texts))
            self.assertLessEqual(len(refusals), 1, "not throttled: %r" % refusals)
            self.assertIsNotNone(warning_key(refusals[0]), refusals[0])
        tf_refusals = [t for t in texts if t.startswith("tf refused") and "last_frame" in t]
        self.assertEqual(len(tf_refusals), 1, "tf at stamp %d s: %r" % (last.secs, texts))
        self.assertIn("time out of range", tf_refusals[0])
        yarn = support.find_yarn(self.states.latest(), "b")
        self.assertNotIn(3, list(yarn.support_vertices), "the refused grasp was taken")
        yarn = support.find_yarn(self.states.latest(), "a")
        self.assertNotIn(4, list(yarn.support_vertices), "a grasp on the refused frame was taken")


    def test_5_force_far_past_the_vertexs_strength_is_refused(self):
        # yarn a's last vertex has one edge: sigma_b pi r^2 of it, times 100, is the bound
        yarn = self.config["yarns"][0]
        strength = yarn["material"]["stress_strain"][-1][1] * math.pi * yarn["radius"] ** 2
        time.sleep(2.5)  # past the throttle of any earlier out-of-bounds warning
        breaks_before = len(self.breaks.messages())
        since = time.monotonic()
        self.force("a", -1, (0.0, 0.0, -2.0 * 100.0 * strength))
        time.sleep(1.0)
        self.assertEqual(node_pid(), self.pid, "the node restarted or died")
        refusals = [t for t in self.logs.texts(since=since)
                    if t.startswith("applied_force refused (out of bounds")]
        self.assertEqual(len(refusals), 1, refusals)
        self.assertIn("100 x its segments' breaking forces", refusals[0])
        self.assertEqual(len(self.breaks.messages()), breaks_before, "the refused force tore")

if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "hostile_messages", HostileMessagesTest)
