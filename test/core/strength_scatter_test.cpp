// Strength scatter given as a coefficient of variation, as yarn strength is usually reported.
#include "yarn_tearing/core/material/strength_scatter.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

TEST(StrengthScatter, ModulusForACoefficientOfVariationMatchesClosedForms) {
  // m = 1 is the exponential distribution (CV = 1); m = 2 the Rayleigh, CV = sqrt(4/pi - 1).
  EXPECT_NEAR(weibullModulusForCoefficientOfVariation(1.0), 1.0, 1e-9);
  EXPECT_NEAR(weibullModulusForCoefficientOfVariation(std::sqrt(4.0 / kPi - 1.0)), 2.0, 1e-9);
}

TEST(StrengthScatter, SampledFactorsHaveMeanOneAndTheRequestedCoefficientOfVariation) {
  // 200,000 factors at CV 0.1: the sample mean's standard error is 0.1 / sqrt(n) = 2.2e-4 and
  // the sample CV's about CV / sqrt(2 n) = 1.6e-4, so 0.2 % and 2 % are each over nine standard
  // errors; the seed makes the draw fixed anyway.
  StrengthScatter scatter;
  scatter.coefficient_of_variation = 0.1;
  scatter.seed = 3;
  // Edges of the gauge length: each one is a specimen.
  const std::vector<double> factors =
      strengthFactors(scatter, std::vector<double>(200000, scatter.gauge_length));
  double sum = 0.0;
  double sum2 = 0.0;
  for (double f : factors) {
    sum += f;
    sum2 += f * f;
  }
  const double n = static_cast<double>(factors.size());
  const double mean = sum / n;
  const double sd = std::sqrt((sum2 - n * mean * mean) / (n - 1.0));
  EXPECT_NEAR(mean, 1.0, 2e-3);
  EXPECT_NEAR(sd / mean, 0.1, 0.1 * 0.02);
}

TEST(StrengthScatter, ModulusAndCoefficientOfVariationAreNotBothAccepted) {
  YarnSpec spec = hangingYarn();
  spec.strength_scatter.weibull_modulus = 10.0;
  spec.strength_scatter.coefficient_of_variation = 0.1;
  EXPECT_THROW(spec.validate(), std::invalid_argument);
  spec.strength_scatter.weibull_modulus = 0.0;
  EXPECT_NO_THROW(spec.validate());
  spec.strength_scatter.coefficient_of_variation = 1.5;
  EXPECT_THROW(spec.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace yarn_tearing::test
