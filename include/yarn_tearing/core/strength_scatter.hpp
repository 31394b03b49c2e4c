#pragma once

#include <cstddef>
#include <vector>

#include "yarn_tearing/core/yarn_spec.hpp"

namespace yarn_tearing {

/// Breaking-strain factors [-] of `count` edges, Weibull distributed with mean 1 (all 1 when the
/// modulus is 0). Uses splitmix64 so the factors are the same on every platform for a seed.
std::vector<double> strengthFactors(const StrengthScatter& scatter, std::size_t count);

}  // namespace yarn_tearing
