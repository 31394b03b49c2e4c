#pragma once

#include <string>

#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// YAML text describing each yarn's material, published latched on yarn_materials:
///   <yarn name>:
///     material: <preset name or inline>
///     breaking_stress: [Pa]    breaking_strain: [-]
///     yield_stress: [Pa]       yield_strain: [-]
///     youngs_modulus: [Pa]     area: [m^2] (load-bearing)   radius: [m]
///     weakest_breaking_force: [N] (see weakestBreakingForce)
///     density: [kg/m^3]        rate_sensitivity: [-, per decade of strain rate]
///     curve: [[strain, stress [Pa]], ...]
/// Every number is written so that YAML 1.1 readers (PyYAML) parse it as a float.
std::string describeMaterialsYaml(const Scene& scene);

/// Tension [N] at which `yarn`'s weakest edge tears: the minimum over its edges e of
/// sigma_b * strength_factor_e * area_e. Equals sigma_b * area without strength scatter.
double weakestBreakingForce(const Scene& scene, const Yarn& yarn);

/// `x` as a YAML float, e.g. 3.0e+08, 0.01, 0.0 (PyYAML needs a '.' before an exponent).
std::string yamlFloat(double x);

/// `text` as a double-quoted YAML scalar.
std::string yamlQuoted(const std::string& text);

}  // namespace ros_layer
}  // namespace yarn_tearing
