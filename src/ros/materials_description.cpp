#include "yarn_tearing/ros/materials_description.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>

namespace yarn_tearing {
namespace ros_layer {

std::string yamlFloat(double x) {
  if (std::isnan(x)) {
    return ".nan";
  }
  if (std::isinf(x)) {
    return x > 0.0 ? ".inf" : "-.inf";
  }
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.9g", x);
  std::string text(buffer);
  if (text.find('.') == std::string::npos) {
    const std::size_t exponent = text.find('e');
    text.insert(exponent == std::string::npos ? text.size() : exponent, ".0");
  }
  return text;
}

std::string yamlQuoted(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
    }
    quoted += c;
  }
  return quoted + "\"";
}

double weakestBreakingForce(const Scene& scene, const Yarn& yarn) {
  const double breaking_stress = yarn.material.curve.breakingStress();
  double weakest = std::numeric_limits<double>::infinity();
  for (std::uint32_t e = yarn.first_edge; e < yarn.first_edge + yarn.num_edges; ++e) {
    weakest = std::min(
        weakest, breaking_stress * scene.edges.strength_factor.at(e) * scene.edges.area.at(e));
  }
  return weakest;
}

std::string describeMaterialsYaml(const Scene& scene) {
  std::ostringstream yaml;
  for (const Yarn& yarn : scene.yarns) {
    const StressStrainCurve& curve = yarn.material.curve;
    yaml << yamlQuoted(yarn.name) << ":\n";
    yaml << "  material: " << yamlQuoted(yarn.material.name) << "\n";
    yaml << "  breaking_stress: " << yamlFloat(curve.breakingStress()) << "\n";
    yaml << "  breaking_strain: " << yamlFloat(curve.breakingStrain()) << "\n";
    yaml << "  yield_stress: " << yamlFloat(curve.yieldStress()) << "\n";
    yaml << "  yield_strain: " << yamlFloat(curve.yieldStrain()) << "\n";
    yaml << "  youngs_modulus: " << yamlFloat(curve.youngsModulus()) << "\n";
    yaml << "  area: " << yamlFloat(scene.edges.area.at(yarn.first_edge)) << "\n";
    yaml << "  weakest_breaking_force: " << yamlFloat(weakestBreakingForce(scene, yarn)) << "\n";
    yaml << "  radius: " << yamlFloat(yarn.radius) << "\n";
    yaml << "  density: " << yamlFloat(yarn.material.density) << "\n";
    yaml << "  rate_sensitivity: " << yamlFloat(yarn.material.rate_sensitivity) << "\n";
    yaml << "  curve: [";
    bool first = true;
    for (const CurvePoint& point : curve.points()) {
      yaml << (first ? "" : ", ") << "[" << yamlFloat(point.strain) << ", "
           << yamlFloat(point.stress) << "]";
      first = false;
    }
    yaml << "]\n";
  }
  return yaml.str();
}

}  // namespace ros_layer
}  // namespace yarn_tearing
