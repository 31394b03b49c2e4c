#include "yarn_tearing/core/material/strength_scatter.hpp"

#include <cmath>
#include <cstdint>

namespace yarn_tearing {
namespace {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace

double weibullCoefficientOfVariation(double modulus) {
  const double mean = std::tgamma(1.0 + 1.0 / modulus);
  return std::sqrt(std::tgamma(1.0 + 2.0 / modulus) / (mean * mean) - 1.0);
}

double weibullModulusForCoefficientOfVariation(double cv) {
  // CV(1) = 1 and CV falls towards 0 as m grows (CV ~ 1.28 / m): bracket [1, 1e4].
  double low = 1.0;
  double high = 1.0e4;
  for (int i = 0; i < 200 && high - low > 1e-12 * high; ++i) {
    const double middle = 0.5 * (low + high);
    (weibullCoefficientOfVariation(middle) > cv ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

double weibullModulus(const StrengthScatter& scatter) {
  return scatter.coefficient_of_variation > 0.0
             ? weibullModulusForCoefficientOfVariation(scatter.coefficient_of_variation)
             : scatter.weibull_modulus;
}

std::vector<double> strengthFactors(const StrengthScatter& scatter,
                                    const std::vector<double>& edge_lengths) {
  std::vector<double> factors(edge_lengths.size(), 1.0);
  const double m = weibullModulus(scatter);
  if (m <= 0.0) return factors;
  const double mean = std::tgamma(1.0 + 1.0 / m);  // mean of a unit-scale Weibull
  std::uint64_t state = scatter.seed;
  for (std::size_t e = 0; e < factors.size(); ++e) {
    // Uniform in (0, 1): 53 random bits, offset by half a unit so 0 never occurs.
    const double u = (static_cast<double>(splitmix64(state) >> 11) + 0.5) * 0x1.0p-53;
    // P(f_e > s) = exp(-(length_e / gauge) (s * mean)^m): a longer edge is more likely weak.
    const double scale = std::pow(scatter.gauge_length / edge_lengths[e], 1.0 / m) / mean;
    factors[e] = scale * std::pow(-std::log(u), 1.0 / m);
  }
  return factors;
}

void assignBreakingStrains(const std::vector<Yarn>& yarns, EdgeSet& edges) {
  edges.breaking_strain.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const StressStrainCurve& curve = yarns[edges.yarn[e]].material.curve;
    const double f = edges.strength_factor[e];
    // f = 1 gives the curve's own breaking strain exactly (no interpolation round-off).
    edges.breaking_strain[e] =
        f == 1.0 ? curve.breakingStrain() : curve.strainAtStress(f * curve.breakingStress());
  }
}

}  // namespace yarn_tearing
