#include "yarn_tearing/core/material/material.hpp"

#include <cmath>
#include <stdexcept>

#include "yarn_tearing/core/material/rate_dependence.hpp"

namespace yarn_tearing {

double Material::waveSpeed() const { return std::sqrt(curve.youngsModulus() / density); }

double Material::snapBackSpeed() const { return waveSpeed() * curve.breakingStrain(); }

void Material::validate() const {
  if (!std::isfinite(density) || density <= 0.0) {
    throw std::invalid_argument("material " + name + ": density must be > 0 [kg/m^3], got " +
                                std::to_string(density));
  }
  if (!(rate_sensitivity >= 0.0 && rate_sensitivity <= RateDependence::kMaxSensitivity)) {
    throw std::invalid_argument("material " + name + ": rate_sensitivity must be in [0, " +
                                std::to_string(RateDependence::kMaxSensitivity) +
                                "] (per decade of strain rate), got " +
                                std::to_string(rate_sensitivity));
  }
}

}  // namespace yarn_tearing
