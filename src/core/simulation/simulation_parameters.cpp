#include "yarn_tearing/core/simulation/simulation_parameters.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace yarn_tearing {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

void SimulationParameters::validate() const {
  require(std::isfinite(time_step) && time_step > 0.0 && time_step <= 0.1,
          "time_step must be in (0, 0.1] [s], got " + std::to_string(time_step));
  require(gravity.allFinite(), "gravity must be finite [m/s^2]");
  require(std::isfinite(air_damping) && air_damping >= 0.0,
          "air_damping must be >= 0 [N*s/m^2], got " + std::to_string(air_damping));
  require(std::isfinite(soft_spring_ratio) && soft_spring_ratio >= 0.0 && soft_spring_ratio < 1.0,
          "soft_spring_ratio must be in [0, 1), got " + std::to_string(soft_spring_ratio));
  require(std::isfinite(regularization) && regularization >= 0.0 && regularization < 1.0,
          "regularization must be in [0, 1), got " + std::to_string(regularization));
  require(std::isfinite(constraint_tolerance) && constraint_tolerance > 0.0 &&
              constraint_tolerance < 0.1,
          "constraint_tolerance must be in (0, 0.1), got " + std::to_string(constraint_tolerance));
  require(max_projection_iterations >= 1 && max_projection_iterations <= 10000,
          "max_projection_iterations must be in [1, 10000], got " +
              std::to_string(max_projection_iterations));
  require(recoil_substeps >= 1 && recoil_substeps <= 10000,
          "recoil_substeps must be in [1, 10000], got " + std::to_string(recoil_substeps));
  require(threads >= 1 && threads <= 1024,
          "threads must be in [1, 1024], got " + std::to_string(threads));
}

}  // namespace yarn_tearing
