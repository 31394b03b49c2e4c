// The virtual trouser tear test's report (force peaks, their mean and spread, the force–extension
// curve) and the textile literature's relation it must show: the tear force scales with the
// strength of the single yarns that break, so doubling the weft yarn's breaking force (a yarn of
// twice the cross-section) doubles the mean tear force, within the spread of the peaks.
#include "yarn_tearing/core/trouser_tear.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

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

}  // namespace
}  // namespace yarn_tearing::test
