#pragma once

#include <string>

#include "yarn_tearing/core/stress_strain_curve.hpp"

namespace yarn_tearing {

/// Mechanical properties of a yarn's fibre material.
struct Material {
  std::string name;                ///< preset name or "inline"
  double density = 1500.0;         ///< fibre density [kg/m^3]
  double plastic_viscosity = 0.0;  ///< plastic flow viscosity eta [Pa*s]; 0 = rate-independent
  StressStrainCurve curve{{{0.0, 0.0}, {0.01, 1.0e8}, {0.07, 3.0e8}}};  ///< loading curve

  /// Throws std::invalid_argument naming the field unless density > 0 and viscosity >= 0.
  void validate() const;
};

}  // namespace yarn_tearing
