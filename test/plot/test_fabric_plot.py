"""Tests of plot_bag's fabric figures (scripts/yarn_plotting/fabric.py) on a synthetic bag.

A 3 x 2 fabric (row 0 pinned, vertices 0-2; row 1 = vertices 3-5): grips on vertices 3 and 5
drawn apart along x at SPEED each; the force they feel rises linearly to PEAKS[k] at
BREAKS[k] - 1/RATE and drops by half at the break, where a BreakEvent is recorded (the state of
that step is left out of the curve).
Run: /usr/bin/python3 -m unittest discover -s test/plot -v
"""

import contextlib
import io
import os
import shutil
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.normpath(os.path.join(HERE, "..", "..", "scripts")))

import synthetic_bag as sb  # noqa: E402
from yarn_plotting.fabric import FIGURES, make_fabric_figures  # noqa: E402

RATE = 30.0                    # [Hz]
SPEED = 0.01                   # [m/s] each grip
BREAKS = (0.5, 1.0, 1.5)       # [s] simulated time of each tear (on a sample)
PEAKS = (2.0, 3.0, 2.5)        # [N] the force just before each tear
DURATION = 2.0                 # [s]
SPACING = 0.01                 # [m]


def classes():
    import genpy.dynamic

    def read(name):
        with open(os.path.join(sb.MSG_DIR, name + ".msg")) as f:
            return f.read()

    deps = dict(sb.DEPS, **{sb.PKG + "/FabricState": read("FabricState")})
    text = "".join(sb.SEP + "MSG: %s\n%s\n" % kv for kv in deps.items())
    out = {}
    for name in ("FabricStateArray", "BreakEvent"):
        types = genpy.dynamic.generate_dynamic(sb.PKG + "/" + name, read(name) + "\n" + text)
        out.update({k.split("/")[-1]: v for k, v in types.items()})
    return out


def force(t):
    """[N] the grips' force at t: ramps to each peak, half of it after the tear."""
    start_t, start_f = 0.0, 0.0
    for b, p in zip(BREAKS, PEAKS):
        if t < b - 1e-9:
            return start_f + (p - start_f) * (t - start_t) / (b - 1.0 / RATE - start_t)
        start_t, start_f = b, 0.5 * p
    return start_f


def write_bag(path):
    import rosbag
    import rospy

    c = classes()
    edges = [0, 1, 1, 2, 3, 4, 4, 5, 0, 3, 1, 4, 2, 5]
    with rosbag.Bag(path, "w") as bag:
        for i in range(int(DURATION * RATE) + 1):
            t = i / RATE
            stamp = rospy.Time.from_sec(t)
            travel = SPEED * t
            xs = [0, SPACING, 2 * SPACING, -travel, SPACING, 2 * SPACING + travel]
            zs = [0, 0, 0, -SPACING, -SPACING, -SPACING]
            f = c["FabricState"](name="cloth", ends=3, picks=2)
            f.positions = [c["Point"](x=x, y=0.0, z=z) for x, z in zip(xs, zs)]
            f.velocities = [c["Vector3"]() for _ in xs]
            f.edge_vertices = edges
            n = len(edges) // 2
            f.stresses = [1.0e8 * force(t)] * n
            f.broken = [i_e == 3 and t >= BREAKS[0] for i_e in range(n)]
            f.support_vertices = [0, 1, 2, 3, 5]
            f.support_forces = [c["Vector3"]() for _ in range(3)] + [
                c["Vector3"](x=force(t)), c["Vector3"](x=-force(t))]
            msg = c["FabricStateArray"](sim_time=t, fabrics=[f])
            msg.header.stamp, msg.header.frame_id = stamp, "world"
            bag.write("/fabric_states", msg, stamp)
            if any(abs(t - b) < 1e-9 for b in BREAKS):
                ev = c["BreakEvent"](yarn="cloth/weft", fabric="cloth", family=1, sim_time=t)
                ev.header.stamp = stamp
                bag.write("/break_events", ev, stamp)


class FabricPlotTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="fabric_plot_test_")
        cls.bag = os.path.join(cls.tmp, "fabric.bag")
        write_bag(cls.bag)
        cls.result = make_fabric_figures(cls.bag, os.path.join(cls.tmp, "out"))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_peaks_are_the_forces_before_each_tear(self):
        curve = self.result["curve"]
        np.testing.assert_allclose(curve.peaks, PEAKS, rtol=1e-9)
        self.assertAlmostEqual(curve.mean_peak, np.mean(PEAKS), places=9)

    def test_extension_is_the_grips_separation_growth(self):
        curve = self.result["curve"]
        t = np.arange(len(curve.extension)) / RATE
        np.testing.assert_allclose(curve.extension, 2 * SPEED * t, atol=1e-12)
        tear_step = np.array([any(abs(x - b) < 1e-9 for b in BREAKS) for x in t])
        self.assertTrue(np.all(np.isnan(curve.force[tear_step])))  # left out: the stop's force
        np.testing.assert_allclose(curve.force[~tear_step], [force(x) for x in t[~tear_step]],
                                   atol=1e-9)

    def test_writes_both_figures(self):
        self.assertEqual(set(self.result["paths"]), set(FIGURES))
        for path in self.result["paths"].values():
            with open(path, "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
            self.assertGreater(os.path.getsize(path), 10000, path)

    def test_plot_bag_draws_a_bag_with_fabrics_only(self):
        sys.argv = ["plot_bag"]
        import importlib.machinery
        import importlib.util

        script = os.path.join(HERE, "..", "..", "scripts", "plot_bag")
        loader = importlib.machinery.SourceFileLoader("plot_bag_script", script)
        spec = importlib.util.spec_from_loader("plot_bag_script", loader)
        module = importlib.util.module_from_spec(spec)
        loader.exec_module(module)
        out = os.path.join(self.tmp, "cli")
        stdout, stderr = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
            status = module.main([self.bag, out])
        self.assertEqual(status, 0, stderr.getvalue())
        self.assertEqual(sorted(os.path.basename(p) for p in stdout.getvalue().split()),
                         ["fabric_filmstrip.png", "tear_force.png"])
        self.assertIn("3 peaks", stderr.getvalue())


if __name__ == "__main__":
    unittest.main()
