#include "yarn_tearing/core/material.hpp"

#include <cmath>
#include <stdexcept>

namespace yarn_tearing {

void Material::validate() const {
  if (!std::isfinite(density) || density <= 0.0) {
    throw std::invalid_argument("material " + name + ": density must be > 0 [kg/m^3], got " +
                                std::to_string(density));
  }
  if (!std::isfinite(plastic_viscosity) || plastic_viscosity < 0.0) {
    throw std::invalid_argument("material " + name +
                                ": plastic_viscosity must be >= 0 [Pa*s], got " +
                                std::to_string(plastic_viscosity));
  }
}

}  // namespace yarn_tearing
