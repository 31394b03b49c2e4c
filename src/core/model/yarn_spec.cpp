#include "yarn_tearing/core/model/yarn_spec.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace yarn_tearing {
namespace {

constexpr double kPi = 3.14159265358979323846;

void requireYarn(bool ok, const std::string& yarn, const std::string& what) {
  if (!ok) throw std::invalid_argument("yarn '" + yarn + "': " + what);
}

}  // namespace

void YarnSpec::validate() const {
  requireYarn(!name.empty(), name, "name must not be empty");
  try {
    material.validate();
  } catch (const std::invalid_argument& e) {
    requireYarn(false, name, e.what());
  }
  if (tex > 0.0) {
    requireYarn(std::isfinite(tex), name, "tex must be finite and > 0 [g/km]");
    requireYarn(packing_fraction > 0.0 && packing_fraction <= 1.0, name,
                "packing_fraction must be in (0, 1], got " + std::to_string(packing_fraction));
  } else {
    requireYarn(tex == 0.0, name, "tex must be >= 0 [g/km], got " + std::to_string(tex));
    requireYarn(std::isfinite(radius) && radius > 0.0, name,
                "radius must be > 0 [m], got " + std::to_string(radius));
  }
  requireYarn(std::isfinite(length) && length > 0.0, name,
              "length must be > 0 [m], got " + std::to_string(length));
  requireYarn(num_vertices >= 2, name,
              "num_vertices must be >= 2, got " + std::to_string(num_vertices));
  requireYarn(start.allFinite(), name, "start must be finite [m]");
  requireYarn(direction.allFinite() && direction.norm() > 0.0, name,
              "direction must be a finite non-zero vector");
  for (int p : pinned) {
    requireYarn(p >= -num_vertices && p < num_vertices, name,
                "pinned index " + std::to_string(p) + " out of range [" +
                    std::to_string(-num_vertices) + ", " + std::to_string(num_vertices - 1) + "]");
  }
  requireYarn(std::isfinite(end_mass) && end_mass >= 0.0, name,
              "end_mass must be >= 0 [kg], got " + std::to_string(end_mass));
  requireYarn(
      std::isfinite(strength_scatter.weibull_modulus) && strength_scatter.weibull_modulus >= 0.0,
      name, "weibull_modulus must be >= 0 (0 = no scatter)");
  const double cv = strength_scatter.coefficient_of_variation;
  requireYarn(
      std::isfinite(cv) && cv >= 0.0 && cv <= 1.0, name,
      "strength coefficient of variation must be in [0, 1] (0 = none), got " + std::to_string(cv));
  requireYarn(
      cv == 0.0 || strength_scatter.weibull_modulus == 0.0, name,
      "give the strength scatter as a Weibull modulus or as a coefficient of variation, not "
      "both");
  const double gauge = strength_scatter.gauge_length;
  requireYarn(std::isfinite(gauge) && gauge > 0.0, name,
              "gauge_length must be > 0 [m], got " + std::to_string(gauge));
}

double YarnSpec::area() const {
  if (tex > 0.0) return tex * 1.0e-6 / material.density;
  return kPi * radius * radius;
}

double YarnSpec::linearDensity() const { return material.density * area(); }

double YarnSpec::effectiveRadius() const {
  if (tex > 0.0) return std::sqrt(area() / (kPi * packing_fraction));
  return radius;
}

}  // namespace yarn_tearing
