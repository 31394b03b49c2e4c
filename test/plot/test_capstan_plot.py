"""Tests of plot_bag's capstan figure (scripts/yarn_plotting/capstan.py) on a synthetic yarn
wrapped over a peg: two vertical tails joined over the top (theta = pi), the pulled tail's
tension rising as T_first * e^(mu pi) until a tear.

Run:  /usr/bin/python3 -m unittest discover -s test/plot -v
"""

import os
import shutil
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.normpath(os.path.join(HERE, "..", "..", "scripts")))

from yarn_plotting.bagdata import BagData, BreakRecord, YarnSeries  # noqa: E402
from yarn_plotting.capstan import capstan_series, make_capstan  # noqa: E402

MU = 0.3
TEAR = 0.8  # [s]


def wrapped_yarn(n_states=20):
    """A 6-vertex yarn: up the left tail (x = -1 cm), over the top, down the right tail; edge 0
    carries 1 N * t, the last edge e^(mu pi) times as much; after TEAR the yarn is torn."""
    shape = np.array([[-0.01, 0, -0.05], [-0.01, 0, 0.0], [-0.005, 0, 0.005], [0.005, 0, 0.005],
                      [0.01, 0, 0.0], [0.01, 0, -0.05]])
    t = np.linspace(0.0, 1.0, n_states)
    first = 1.0 * t
    tensions = np.repeat(first[:, None], 5, axis=1)
    tensions[:, 4] = first * np.exp(MU * np.pi)
    tensions[t >= TEAR] = 0.0
    edges = np.repeat(np.array([[[i, i + 1] for i in range(5)]]), n_states, axis=0)
    nan = np.full((n_states, 5), np.nan)
    return YarnSeries(name="yarn", t=t, positions=np.repeat(shape[None], n_states, axis=0),
                      velocities=np.full((n_states, 6, 3), np.nan), edges=edges,
                      rest_lengths=nan, tensions=tensions, stresses=nan, strains=nan,
                      plastic_strains=nan, broken=np.zeros((n_states, 5), bool),
                      supports=[np.array([0, 5])] * n_states)


class CapstanPlotTest(unittest.TestCase):
    def setUp(self):
        self.out = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.out)

    def test_wrap_angle_and_ratio_before_the_tear(self):
        series = capstan_series(wrapped_yarn(), TEAR)
        self.assertTrue(np.all(series.t < TEAR))
        np.testing.assert_allclose(series.theta, np.pi, atol=1e-12)
        ratio = series.ratio()
        self.assertTrue(np.isnan(ratio[0]))  # the unloaded first state: no ratio
        np.testing.assert_allclose(ratio[2:], np.exp(MU * np.pi), rtol=1e-12)

    def test_writes_the_figure_and_the_last_ratio(self):
        tear = BreakRecord(t=TEAR, yarn="yarn", edge=4, position=np.zeros(3), tension=10.0,
                           stress=1.0e9, strain=0.05, plastic_strain=0.0)
        data = BagData(yarns={"yarn": wrapped_yarn()}, breaks=[tear], metadata=None,
                       time_origin=0.0)
        path = os.path.join(self.out, "capstan.png")
        info = make_capstan(data, "yarn", MU, path)
        with open(path, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertAlmostEqual(info["final_ratio"], np.exp(MU * np.pi), places=12)
        self.assertAlmostEqual(info["final_law"], np.exp(MU * np.pi), places=12)
        self.assertAlmostEqual(info["final_theta"], np.pi, places=12)


if __name__ == "__main__":
    unittest.main()
