"""Tests of scripts/plot_bag on synthetic bags (see synthetic_bag.py).

Run:  /usr/bin/python3 -m unittest discover -s test/plot -v
(needs python3-rosbag, python3-genpy, python3-matplotlib, python3-numpy,
python3-yaml; no built package and no roscore).  With
YARN_TEARING_BAG=<bag recorded from the node> it also checks that bag.
"""

import contextlib
import io
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.normpath(os.path.join(HERE, "..", "..", "scripts"))
sys.path.insert(0, HERE)
sys.path.insert(0, SCRIPTS)

import synthetic_bag as sb  # noqa: E402
from yarn_plotting import BagError, FIGURES, frames, make_all, read_bag  # noqa: E402
from yarn_plotting.curves import dash_styles  # noqa: E402
from yarn_plotting.filmstrip import projection_axes  # noqa: E402
from yarn_plotting.materials import Material, load_presets  # noqa: E402

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def bag_break_stamps(path):
    """header.stamp [s] of every BreakEvent in the bag, read independently."""
    import rosbag

    with rosbag.Bag(path) as bag:
        return sorted(m.header.stamp.to_sec() for _, m, _ in bag.read_messages()
                      if m._type.endswith("/BreakEvent"))


def assert_pngs(test, paths):
    """The four figures, as non-trivial PNG files."""
    test.assertEqual(set(paths), set(FIGURES))
    for name, path in paths.items():
        test.assertEqual(os.path.basename(path), name + ".png")
        with open(path, "rb") as f:
            test.assertEqual(f.read(8), PNG_MAGIC, path)
        test.assertGreater(os.path.getsize(path), 10000, path)


class PlotBagTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="plot_bag_test_")
        cls.bag = os.path.join(cls.tmp, "demo.bag")
        cls.t_breaks = sb.write_bag(cls.bag)
        cls.out = os.path.join(cls.tmp, "out")
        cls.result = make_all(cls.bag, cls.out)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def bag_path(self, name, **kwargs):
        path = os.path.join(self.tmp, name)
        sb.write_bag(path, **kwargs)
        return path

    def assert_pngs(self, paths):
        assert_pngs(self, paths)

    def test_writes_the_four_figures(self):
        self.assert_pngs(self.result["paths"])

    def test_break_lines_are_the_break_event_stamps(self):
        stamps = bag_break_stamps(self.bag)
        self.assertEqual(len(stamps), 2)
        self.assertEqual(self.result["time_origin"], 0.0)
        np.testing.assert_allclose(sorted(self.result["break_times"]), stamps, atol=1e-9)
        np.testing.assert_allclose(stamps, sorted(self.t_breaks.values()), atol=1e-9)

    def test_wall_clock_stamps_are_shifted_to_start_at_zero(self):
        t0 = 1.7e9
        bag = self.bag_path("wall.bag", t0=t0, ns="/robot/sim")
        res = make_all(bag, os.path.join(self.tmp, "wall"))
        self.assertAlmostEqual(res["time_origin"], t0, places=3)
        drawn = np.array(sorted(res["break_times"]))
        np.testing.assert_allclose(drawn + res["time_origin"], bag_break_stamps(bag), atol=1e-6)
        np.testing.assert_allclose(drawn, sorted(self.t_breaks.values()), atol=1e-6)

    def test_frames_span_load_to_recoil(self):
        data = read_bag(self.bag)
        times = np.array(self.result["frame_times"])
        self.assertEqual(len(times), 8)
        self.assertTrue(np.all(np.diff(times) > 0))
        self.assertAlmostEqual(times[0], frames.load_onset(data))
        self.assertGreater(times[0], 0.0)  # zero tension at t = 0 is not "load"
        self.assertGreater(times[-1], sb.STRONG_BREAK)
        for t in (sb.WEAK_BREAK, sb.STRONG_BREAK):  # the tear and the state just before
            self.assertTrue(np.any(np.isclose(times, t)), (t, times))
            self.assertTrue(np.any(np.isclose(times, t - 1 / sb.RATE)), (t, times))

    def test_material_from_metadata_topic(self):
        st = self.result["strengths"]
        for name in ("weak", "strong"):
            self.assertEqual(st[name].source, "bag metadata")
            self.assertAlmostEqual(st[name].breaking_stress, sb.MATERIALS[name]["breaking_stress"])
            self.assertAlmostEqual(st[name].area / sb.AREA, 1.0, places=9)
            self.assertAlmostEqual(st[name].material.area / sb.AREA, 1.0, places=6)
            self.assertAlmostEqual(st[name].material.yield_strain,
                                   sb.MATERIALS[name]["yield_strain"])
            np.testing.assert_allclose(st[name].material.curve, sb.MATERIALS[name]["curve"])

    def test_weakest_edge_line_only_where_strength_scatter_shows(self):
        lines = self.result["info"]["tension_strain"]["weakest_lines"]
        self.assertEqual(set(lines), {"weak"})  # strong's is within 0.1 % of sigma_b pi r^2
        self.assertAlmostEqual(lines["weak"] / sb.WEAKEST_FORCE["weak"], 1.0, places=6)
        self.assertLess(lines["weak"], self.result["strengths"]["weak"].breaking_force)
        styles = dash_styles({"weak": 5.0, "released": 5.0, "strong": 20.0})
        self.assertEqual(styles["strong"], "--")
        self.assertNotEqual(styles["weak"], styles["released"])  # interleaved, both visible

    def test_without_metadata_sigma_b_from_break_event(self):
        bag = self.bag_path("nometa.bag", with_metadata=False)
        res = make_all(bag, os.path.join(self.tmp, "nometa"))
        self.assert_pngs(res["paths"])
        for name in ("weak", "strong"):
            st = res["strengths"][name]
            self.assertEqual(st.source, "break event")
            self.assertIsNone(st.material)
            self.assertAlmostEqual(st.breaking_force / (sb.MATERIALS[name]["breaking_stress"]
                                                        * sb.AREA), 1.0, places=9)
        self.assertEqual(res["info"]["tension_strain"]["weakest_lines"], {})

    def test_without_breaks_or_material(self):
        bag = self.bag_path("nobreaks.bag", with_metadata=False, with_breaks=False)
        res = make_all(bag, os.path.join(self.tmp, "nobreaks"))
        self.assert_pngs(res["paths"])
        self.assertEqual(res["break_times"], [])
        self.assertEqual({s.source for s in res["strengths"].values()}, {"unknown"})
        # the tears are still found from the broken flags for the filmstrip
        self.assertTrue(np.any(np.isclose(res["frame_times"], sb.WEAK_BREAK)))

    def test_material_file_preset_overrides(self):
        presets = os.path.join(self.tmp, "materials.yaml")
        with open(presets, "w") as f:
            f.write("materials:\n  cotton: {breaking_stress: 2.0e8, yield_stress: 1.0e8,\n"
                    "           young_modulus: 1.0e10, breaking_strain: 0.04}\n")
        res = make_all(self.bag, os.path.join(self.tmp, "preset"), material_file=presets,
                       assignments={"weak": "cotton"})
        weak, strong = res["strengths"]["weak"], res["strengths"]["strong"]
        self.assertEqual(weak.source, "preset cotton")
        self.assertEqual(weak.breaking_stress, 2.0e8)
        self.assertAlmostEqual(weak.material.yield_strain, 0.01)
        self.assertEqual(weak.material.curve.shape, (3, 2))
        self.assertEqual(strong.source, "bag metadata")
        for bad in ({"weak": "silk"}, {"wea": "cotton"}):  # unknown preset, unknown yarn
            with self.assertRaises(KeyError):
                make_all(self.bag, self.tmp, material_file=presets, assignments=bad)

    def test_presets_of_the_package_material_file(self):
        path = os.path.join(SCRIPTS, "..", "config", "materials.yaml")
        if not os.path.exists(path):
            self.skipTest("no config/materials.yaml")
        presets = load_presets(path)
        self.assertTrue(presets)
        for name, preset in presets.items():
            m = Material.from_dict(preset)
            curve = np.asarray(preset["stress_strain"], dtype=float)
            self.assertEqual((m.breaking_strain, m.breaking_stress), tuple(curve[-1]), name)
            self.assertEqual((m.yield_strain, m.yield_stress), tuple(curve[1]), name)
        first = sorted(presets)[0]
        res = make_all(self.bag, os.path.join(self.tmp, "pkg_presets"), material_file=path,
                       assignments={"strong": first})
        self.assertEqual(res["strengths"]["strong"].source, "preset " + first)
        self.assert_pngs(res["paths"])

    def test_reset_plots_the_last_run(self):
        bag = self.bag_path("reset.bag", reset=True)
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            res = make_all(bag, os.path.join(self.tmp, "reset"))
            n_samples = len(read_bag(bag).yarns["weak"].t)
        self.assertIn("plotting only the last run", err.getvalue())
        np.testing.assert_allclose(sorted(res["break_times"]), sorted(self.t_breaks.values()))
        self.assertEqual(n_samples, len(read_bag(self.bag).yarns["weak"].t))

    def test_stress_strain_uses_the_most_stressed_edge(self):
        self.assertEqual(self.result["info"]["stress_strain"]["edges"], sb.TEAR_EDGE)

    def test_length_shows_permanent_elongation(self):
        info = self.result["info"]["length"]
        for name in ("weak", "strong"):
            self.assertAlmostEqual(info["original_lengths"][name], sb.N_EDGES * sb.REST)
            self.assertGreater(info["elongations"][name], 0.01)

    def test_overlapping_yarns_are_drawn_side_by_side(self):
        bag = self.bag_path("overlap.bag", overlap=True)
        res = make_all(bag, os.path.join(self.tmp, "overlap"), n_frames=5)
        film = res["info"]["filmstrip"]
        self.assertEqual(film["plane"], "xz")
        self.assertEqual(len(film["times"]), 5)
        shifts = sorted(film["offsets"].values())
        self.assertGreater(shifts[1] - shifts[0], 0.05)  # about 0.3 x yarn length apart
        self.assertEqual(self.result["info"]["filmstrip"]["offsets"],
                         {"weak": 0.0, "strong": 0.0})  # already apart: kept as is

    def test_projection_axes(self):
        rng = np.random.default_rng(0)
        pts = rng.normal(size=(50, 3))
        self.assertEqual(projection_axes(pts), (0, 2))
        self.assertEqual(projection_axes(pts * [1e-6, 1, 1]), (1, 2))
        self.assertEqual(projection_axes(pts * [1, 1, 1e-6]), (0, 1))
        self.assertEqual(projection_axes(pts * [1, 1e-6, 1]), (0, 2))

    def test_read_bag_errors(self):
        with self.assertRaises(BagError):
            read_bag(os.path.join(self.tmp, "missing.bag"))
        junk = os.path.join(self.tmp, "junk.bag")
        with open(junk, "w") as f:
            f.write("not a bag\n")
        with self.assertRaises(BagError):
            read_bag(junk)
        with self.assertRaisesRegex(BagError, "YarnStateArray"):
            read_bag(self.bag_path("nostates.bag", with_states=False))


@unittest.skipUnless(os.environ.get("YARN_TEARING_BAG"),
                     "set YARN_TEARING_BAG=<bag recorded from the node> to run")
class RecordedBagTest(unittest.TestCase):
    """make_all on a real recording, e.g. roslaunch yarn_tearing demo.launch record:=true."""

    def test_recorded_bag(self):
        bag = os.environ["YARN_TEARING_BAG"]
        with tempfile.TemporaryDirectory() as out:
            res = make_all(bag, out)
            assert_pngs(self, res["paths"])
        stamps = np.array(bag_break_stamps(bag)) - res["time_origin"]
        np.testing.assert_allclose(sorted(res["break_times"]), stamps, atol=1e-6)
        for name, st in res["strengths"].items():
            self.assertIsNotNone(st.breaking_force, name)


class CliTest(unittest.TestCase):
    """scripts/plot_bag as a program (run with this interpreter)."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="plot_bag_cli_")
        cls.bag = os.path.join(cls.tmp, "demo.bag")
        sb.write_bag(cls.bag)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def run_cli(self, *args):
        return subprocess.run([sys.executable, os.path.join(SCRIPTS, "plot_bag"), *args],
                              capture_output=True, text=True, timeout=300)

    def test_prints_the_paths_it_wrote(self):
        out = os.path.join(self.tmp, "out")
        proc = self.run_cli(self.bag, out, "--frames", "6")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        printed = proc.stdout.split()
        self.assertEqual(sorted(printed), sorted(os.path.join(out, n + ".png") for n in FIGURES))
        for path in printed:
            self.assertGreater(os.path.getsize(path), 0)

    def test_missing_bag(self):
        proc = self.run_cli(os.path.join(self.tmp, "nope.bag"), self.tmp)
        self.assertEqual(proc.returncode, 1)
        self.assertIn("cannot read bag", proc.stderr)

    def test_bag_without_yarn_states(self):
        bag = os.path.join(self.tmp, "nostates.bag")
        sb.write_bag(bag, with_states=False)
        proc = self.run_cli(bag, self.tmp)
        self.assertEqual(proc.returncode, 1)
        self.assertIn("no yarn_tearing/YarnStateArray topic", proc.stderr)

    def test_unknown_preset_and_bad_option(self):
        presets = os.path.join(self.tmp, "m.yaml")
        with open(presets, "w") as f:
            f.write("cotton: {breaking_stress: 2.0e8}\n")
        proc = self.run_cli(self.bag, self.tmp, "--material-file", presets,
                            "--material", "weak=silk")
        self.assertEqual(proc.returncode, 2)
        self.assertIn("silk", proc.stderr)
        proc = self.run_cli(self.bag, self.tmp, "--material", "weak")
        self.assertEqual(proc.returncode, 2)

    def test_help_documents_the_breaking_stress(self):
        proc = self.run_cli("--help")
        self.assertEqual(proc.returncode, 0)
        self.assertIn("breaking stress sigma_b", proc.stdout)
        self.assertIn("yarn_materials", proc.stdout)


if __name__ == "__main__":
    unittest.main()
