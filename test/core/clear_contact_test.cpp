// An obstacle within the contact margin of a patch but clear of it: a 3 cm ball pressed 1 mm
// into the middle of a hanging patch whose cells (12.5 mm) are wider than the ball's cap in the
// patch's plane (2 sqrt(2 r d) = 11 mm), so it pokes through a hole between the yarns. Its
// contact points carry nothing, and the patch hangs as it does without the ball (within the
// constraint tolerance), every step converged, at time steps of 1e-4 and 1e-3 s.
#include <gtest/gtest.h>

#include <algorithm>

#include "fabric_support.hpp"

namespace yarn_tearing::test {
namespace {

constexpr double kRadius = 0.015;  ///< the ball's [m]
constexpr double kDepth = 1.0e-3;  ///< how far the ball reaches past the patch's plane [m]

class ClearContact : public ::testing::TestWithParam<double> {};

TEST_P(ClearContact, ABallThroughAHoleOfThePatchCarriesNothingAndThePatchHangsAsWithout) {
  Simulator with_ball = settledPatch(GetParam());
  Simulator without = settledPatch(GetParam());
  const Scene& scene = with_ball.scene();
  // The middle of the patch is the middle of a cell (ends 7 and 8, picks 5 and 6).
  with_ball.setObstacles(
      {ball(patchMiddle(scene) + Eigen::Vector3d(0.0, kRadius - kDepth, 0.0), kRadius)});
  double largest_difference = 0.0;
  for (int k = 0; k < 500; ++k) {
    with_ball.step();
    without.step();
    ASSERT_TRUE(without.lastHealth().projection_converged) << "without, step " << k;
    ASSERT_TRUE(with_ball.lastHealth().projection_converged) << "step " << k;
    ASSERT_FALSE(with_ball.contacts().empty()) << "step " << k;
    for (const Contact& c : with_ball.contacts().contacts()) {
      ASSERT_FALSE(c.active) << "step " << k;
      ASSERT_EQ(c.normal_multiplier, 0.0) << "step " << k;
      ASSERT_EQ(c.friction_impulse.norm(), 0.0) << "step " << k;
      ASSERT_GE(c.gap, 0.0) << "step " << k;
    }
    EXPECT_EQ(with_ball.contactWrench(0).force.norm(), 0.0) << "step " << k;
    for (std::size_t v = 0; v < scene.vertices.size(); ++v) {
      largest_difference =
          std::max(largest_difference,
                   (scene.vertices.position[v] - without.scene().vertices.position[v]).norm());
    }
  }
  // Both solve the same steps to the constraint tolerance (relative to a segment's length).
  EXPECT_LE(largest_difference, with_ball.parameters().constraint_tolerance * kPatchSpacing);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, ClearContact, ::testing::Values(1e-4, 1e-3),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return stepName(info.param);
                         });

}  // namespace
}  // namespace yarn_tearing::test
