#pragma once

#include <string>

#include "yarn_tearing/core/material/stress_strain_curve.hpp"

namespace yarn_tearing {

/// Mechanical properties of a yarn's fibre material.
struct Material {
  std::string name;         ///< preset name or "inline"
  double density = 1500.0;  ///< fibre density [kg/m^3]
  /// Rate sensitivity k [-]: fractional rise of the curve's stresses per decade of strain rate
  /// (RateDependence); 0 = rate-independent.
  double rate_sensitivity = 0.0;
  /// Loading curve at the reference strain rate RateDependence::kReferenceStrainRate.
  StressStrainCurve curve{{{0.0, 0.0}, {0.01, 1.0e8}, {0.07, 3.0e8}}};

  /// Its elastic wave speed c = sqrt(E / rho) [m/s]: how fast a tear's unloading runs through it.
  double waveSpeed() const;
  /// The fastest a yarn of this material moves when released from its breaking strain [m/s]:
  /// c * eps_b with c its waveSpeed() (a snap-back).
  double snapBackSpeed() const;
  /// Throws std::invalid_argument naming the field unless density > 0 and
  /// 0 <= rate_sensitivity <= RateDependence::kMaxSensitivity.
  void validate() const;
};

}  // namespace yarn_tearing
