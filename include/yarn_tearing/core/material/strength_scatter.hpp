#pragma once

#include <cstddef>
#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/model/yarn.hpp"
#include "yarn_tearing/core/model/yarn_spec.hpp"

namespace yarn_tearing {

/// Strength factors f_e [-] of edges of the given rest lengths [m]: edge e tears at the stress
/// f_e * sigma_b (sigma_b the curve's last point). All 1 without scatter. With a Weibull modulus m
/// (given, or the one of the requested CV), the weakest-link law (Peirce 1926): f_e is Weibull of
/// modulus m and scale (gauge_length / length_e)^(1/m) / Gamma(1 + 1/m), so that the weakest edge
/// of any stretch of yarn of length L, however it is meshed, is Weibull of modulus m and scale
/// (gauge_length / L)^(1/m) / Gamma(1 + 1/m): mean 1 and the requested CV at the gauge length.
/// Uses splitmix64, so the factors are the same on every platform for a seed.
std::vector<double> strengthFactors(const StrengthScatter& scatter,
                                    const std::vector<double>& edge_lengths);

/// The Weibull modulus m [-] of a scatter: weibull_modulus, or the one whose coefficient of
/// variation is coefficient_of_variation; 0 = no scatter.
double weibullModulus(const StrengthScatter& scatter);

/// Coefficient of variation [-] of a Weibull distribution of modulus m > 0:
/// sqrt(Gamma(1 + 2/m) / Gamma(1 + 1/m)^2 - 1).
double weibullCoefficientOfVariation(double modulus);

/// The Weibull modulus [-] whose coefficient of variation is `cv` in (0, 1] (bisection on the
/// closed form above, which falls monotonically from 1 at m = 1).
double weibullModulusForCoefficientOfVariation(double cv);

/// Sets each edge's breaking strain [-] from its strength factor: the strain at which the yarn's
/// stress-strain curve (extended past its last point along its last segment) reaches
/// strength_factor * sigma_b. An edge thus follows its material's curve up to its own strength.
void assignBreakingStrains(const std::vector<Yarn>& yarns, EdgeSet& edges);

}  // namespace yarn_tearing
