#include "yarn_tearing/core/material/rate_dependence.hpp"

#include <algorithm>
#include <cmath>

namespace yarn_tearing {

double RateDependence::stressFactor(double sensitivity, double strain_rate) {
  if (sensitivity == 0.0) return 1.0;
  const double rate = std::clamp(strain_rate, kMinStrainRate, kMaxStrainRate);
  return 1.0 + sensitivity * std::log10(rate / kReferenceStrainRate);
}

}  // namespace yarn_tearing
