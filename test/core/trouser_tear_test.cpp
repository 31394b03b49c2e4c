// The virtual trouser tear test's report (force peaks, their mean and spread, the force–extension
// curve) and the textile literature's relation it must show: the tear force scales with the
// strength of the single yarns that break, so doubling the weft yarn's breaking force (a yarn of
// twice the cross-section) doubles the mean tear force, within the spread of the peaks; and it
// rises with the number of yarns sharing the load at the tear's tip (more picks per length).
#include "yarn_tearing/core/lab/trouser_tear.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "fabric_support.hpp"

namespace yarn_tearing::test {
namespace {

/// A 10 x 10 patch, 5 cm square, torn from a 3-pick slit at 0.05 m/s per tongue for 0.3 s.
TrouserTearResult tear(const FabricSpec& spec) {
  SimulationParameters p;
  p.time_step = 1.0e-3;
  return runTrouserTear(p, spec, {3, 0.05, 0.3});
}

TEST(TrouserTear, ReportsOnePeakPerTearAndTheForceExtensionCurve) {
  const FabricSpec spec = cottonPatch(10, 10, 0.05, 0.05);
  const TrouserTearResult result = tear(spec);
  ASSERT_FALSE(result.events.empty());
  ASSERT_EQ(result.curve.size(), 300u);
  EXPECT_NEAR(result.curve.back().extension, 2.0 * 0.05 * 0.3, 1e-12);
  // At most one peak per tear (none between tears in consecutive steps), each on the curve.
  EXPECT_LE(result.peaks.size(), result.events.size());
  EXPECT_GE(result.peaks.size(), 3u);
  double largest = 0.0;
  for (const TrouserTearSample& s : result.curve) largest = std::max(largest, s.force);
  for (const double peak : result.peaks) EXPECT_LE(peak, largest);
  std::printf("tears %zu, peaks", result.events.size());
  for (const double peak : result.peaks) std::printf(" %.4f", peak);
  std::printf(" N; mean %.4f N, spread %.4f N; weft breaking force %.4f N\n", result.mean_peak,
              result.peak_spread, breakingForce(spec.weft));
}

TEST(TrouserTear, DoublingTheWeftStrengthDoublesTheTearForce) {
  FabricSpec spec = cottonPatch(10, 10, 0.05, 0.05);
  // Warp yarns four times as strong as the stronger weft: the tongues hold and the tear runs
  // along the slit's line (with warp as strong as the weft, the strong weft's tear force,
  // twice a warp yarn's strength, tears the tongue off across its warp yarns instead).
  spec.warp.radius *= 2.0 * std::sqrt(2.0);
  const TrouserTearResult base = tear(spec);
  spec.weft.radius *= std::sqrt(2.0);  // twice the cross-section: twice the breaking force
  const TrouserTearResult strong = tear(spec);
  ASSERT_GE(base.peaks.size(), 3u);
  ASSERT_GE(strong.peaks.size(), 3u);
  // The tear ran along the slit's line in both: weft segments between the tongues only.
  for (const TrouserTearResult* run : {&base, &strong}) {
    for (const TearEvent& e : run->events) {
      EXPECT_EQ(e.segment.family, FabricFamily::kWeft);
      EXPECT_EQ(e.segment.segment, static_cast<std::uint32_t>(spec.ends / 2 - 1));
    }
  }
  // Within the spread of the peaks: the strong run's spread and the base run's, doubled.
  const double tolerance = strong.peak_spread + 2.0 * base.peak_spread;
  std::printf("mean peak %.4f +- %.4f N -> %.4f +- %.4f N (ratio %.3f)\n", base.mean_peak,
              base.peak_spread, strong.mean_peak, strong.peak_spread,
              strong.mean_peak / base.mean_peak);
  EXPECT_NEAR(strong.mean_peak, 2.0 * base.mean_peak, tolerance);
}

/// What a trouser tear of a 6-end patch with `picks` picks over 5 cm shows at its force peaks.
struct TipSharing {
  double median_peak = 0.0;  ///< median of the force peaks [N]
  /// Mean over the peaks of the number of weft segments on the slit's line carrying at least a
  /// tenth of the weft's breaking force in the peak's step [-].
  double sharing_yarns = 0.0;
};

TipSharing tearWithPicks(int picks) {
  FabricSpec spec = cottonPatch(6, picks, 0.05, 0.05);
  spec.warp.radius *= 2.0 * std::sqrt(2.0);  // strong tongues, as above
  const double breaking = breakingForce(spec.weft);
  const auto middle = static_cast<std::uint32_t>(spec.ends / 2 - 1);
  std::vector<int> sharing;  // per step
  SimulationParameters p;
  p.time_step = 1.0e-3;
  const TrouserTearResult result =
      runTrouserTear(p, spec, {picks * 3 / 10, 0.05, 0.2}, [&](const Simulator& sim) {
        const Scene& scene = sim.scene();
        int loaded = 0;
        for (int row = 0; row < picks; ++row) {
          const std::uint32_t e =
              scene.fabricEdge(0, {FabricFamily::kWeft, static_cast<std::uint32_t>(row), middle});
          if (!scene.edges.broken[e] && scene.edges.tension[e] >= 0.1 * breaking) ++loaded;
        }
        sharing.push_back(loaded);
      });
  EXPECT_GE(result.peaks.size(), 2u) << picks << " picks";
  TipSharing out;
  for (const double peak : result.peaks) {
    const auto at = std::find_if(result.curve.begin(), result.curve.end(),
                                 [&](const TrouserTearSample& s) { return s.force == peak; });
    out.sharing_yarns += sharing.at(static_cast<std::size_t>(at - result.curve.begin()));
  }
  out.sharing_yarns /= static_cast<double>(std::max<std::size_t>(1, result.peaks.size()));
  std::vector<double> sorted = result.peaks;
  std::sort(sorted.begin(), sorted.end());
  if (!sorted.empty()) out.median_peak = sorted[sorted.size() / 2];
  std::printf(
      "%d picks over 5 cm: median peak %.3f N (%.3f x the weft's breaking force), %.2f "
      "yarns sharing the load at the peaks\n",
      picks, out.median_peak, out.median_peak / breaking, out.sharing_yarns);
  return out;
}

TEST(TrouserTear, TheTearForceRisesWithTheYarnsSharingTheLoadAtTheTip) {
  // The same 5 cm patch and yarns, woven with more picks per length: the tongues' opening angle
  // spreads the tip's load over a length of the slit's line, which holds more picks when they
  // lie closer. Each simulated pick is one yarn of the weft's strength.
  const TipSharing sparse = tearWithPicks(4);
  const TipSharing medium = tearWithPicks(8);
  const TipSharing dense = tearWithPicks(16);
  EXPECT_LT(sparse.sharing_yarns, medium.sharing_yarns);
  EXPECT_LT(medium.sharing_yarns, dense.sharing_yarns);
  EXPECT_LT(sparse.median_peak, medium.median_peak);
  EXPECT_LT(medium.median_peak, dense.median_peak);
  // Never below one yarn's breaking force: the tip's yarn breaks at it, others add to it.
  EXPECT_GE(sparse.median_peak, breakingForce(cottonPatch(6, 4, 0.05, 0.05).weft));
}

}  // namespace
}  // namespace yarn_tearing::test
