"""tensile_test (scripts/) end to end: a few specimens through the tensile_pull executable.

The executable is the one rosrun would run (ws/devel/lib/yarn_tearing), else the core build
(build/core), else $YARN_TEARING_TENSILE_PULL. Without scatter every specimen tears at the
curve's last point, so the report's means are checked against sigma_b * pi r^2 and epsilon_b.
"""

import os
import re
import subprocess
import tempfile
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(REPO, "scripts", "tensile_test")
RELAY = os.path.join(REPO, "ws", "devel", "lib", "yarn_tearing", "tensile_test")


def pull_binary():
    for path in (os.environ.get("YARN_TEARING_TENSILE_PULL", ""),
                 os.path.join(REPO, "ws", "devel", "lib", "yarn_tearing", "tensile_pull"),
                 os.path.join(REPO, "build", "core", "tensile_pull")):
        if path and os.access(path, os.X_OK):
            return path
    raise unittest.SkipTest("tensile_pull is not built")


def run(*args):
    return subprocess.run(["/usr/bin/python3", SCRIPT, "--binary", pull_binary()] + list(args),
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True)


def row(report, label):
    """(mean, CV [%]) of a report row."""
    match = re.search(re.escape(label) + r"\s+(\S+)\s+(\S+)", report)
    return float(match.group(1)), float(match.group(2))


class TensileTest(unittest.TestCase):
    def test_without_scatter_every_specimen_breaks_at_the_curves_last_point(self):
        with tempfile.TemporaryDirectory() as out:
            png = os.path.join(out, "cotton.png")
            # Cotton: sigma_b = 4.86e8 Pa, epsilon_b = 7.1 %, r = 0.1 mm: 15.268 N, 47.75 tex.
            result = run("cotton", "--specimens", "3", "--strength-cv", "0", "--vertices", "6",
                         "--plot", png)
            self.assertEqual(result.returncode, 0, result.stderr)
            force, force_cv = row(result.stdout, "breaking force [N]")
            self.assertAlmostEqual(force, 4.86e8 * 3.14159265e-8, delta=0.01 * 15.27)
            self.assertEqual(force_cv, 0.0)
            tenacity, _ = row(result.stdout, "tenacity [cN/tex]")
            self.assertAlmostEqual(tenacity, 100.0 * force / (3.14159265e-8 * 1520.0 * 1e6),
                                   delta=0.01)
            elongation, _ = row(result.stdout, "elongation at break [%]")
            self.assertAlmostEqual(elongation, 7.1, delta=0.02 * 7.1)
            self.assertGreater(os.path.getsize(png), 10000)

    def test_scatter_gives_each_specimen_its_own_strength(self):
        with tempfile.TemporaryDirectory() as out:
            result = run("polyester", "--specimens", "4", "--vertices", "6",
                         "--plot", os.path.join(out, "p.png"))
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertGreater(row(result.stdout, "breaking force [N]")[1], 0.0)

    def test_inline_material(self):
        with tempfile.TemporaryDirectory() as out:
            result = run("{density: 1520.0, stress_strain: [[0.0, 0.0], [0.01, 5.0e+7], "
                         "[0.05, 1.6e+8]]}", "--specimens", "1", "--strength-cv", "0",
                         "--vertices", "4", "--plot", os.path.join(out, "i.png"))
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertAlmostEqual(row(result.stdout, "breaking force [N]")[0],
                                   1.6e8 * 3.14159265e-8, delta=0.01 * 5.03)

    def test_unknown_preset_and_bad_curve_are_refused(self):
        result = run("no_such_fibre", "--specimens", "1")
        self.assertEqual(result.returncode, 2)
        self.assertIn("no_such_fibre", result.stderr)
        result = run("{density: 1520.0, stress_strain: [[0.0, 0.0], [0.05, 1.6e+8]]}")
        self.assertEqual(result.returncode, 2)
        self.assertIn("at least 3 points", result.stderr)

    @unittest.skipUnless(os.access(RELAY, os.X_OK), "no catkin devel space (tools/build.sh)")
    def test_runs_as_rosrun_runs_it(self):
        # The devel relay finds tensile_pull next to itself, as `rosrun yarn_tearing tensile_test`.
        with tempfile.TemporaryDirectory() as out:
            result = subprocess.run(
                ["/usr/bin/python3", RELAY, "silk", "--specimens", "2", "--vertices", "5",
                 "--plot", os.path.join(out, "s.png")],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("elongation at break [%]", result.stdout)


if __name__ == "__main__":
    unittest.main()
