#pragma once

#include <cstddef>
#include <vector>

#include "yarn_tearing/core/yarn_spec.hpp"

namespace yarn_tearing {

/// Breaking-strain factors [-] of `count` edges, Weibull distributed with mean 1 (all 1 when
/// there is no scatter). Uses splitmix64 so the factors are the same on every platform for a seed.
std::vector<double> strengthFactors(const StrengthScatter& scatter, std::size_t count);

/// Coefficient of variation [-] of a Weibull distribution of modulus m > 0:
/// sqrt(Gamma(1 + 2/m) / Gamma(1 + 1/m)^2 - 1).
double weibullCoefficientOfVariation(double modulus);

/// The Weibull modulus [-] whose coefficient of variation is `cv` in (0, 1] (bisection on the
/// closed form above, which falls monotonically from 1 at m = 1).
double weibullModulusForCoefficientOfVariation(double cv);

}  // namespace yarn_tearing
