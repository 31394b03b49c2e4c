#pragma once

#include "yarn_tearing/core/model/yarn_spec.hpp"
#include "yarn_tearing/ros/param_value.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Reads one entry of ~yarns:
/// {name, material, radius [m] | tex [g/km] (+ packing_fraction [-]), length [m], num_vertices,
///  start [m], direction, pinned (vertex indices, negative from the end), end_mass [kg],
///  weibull_modulus [-] or strength_cv [-], gauge_length [m], seed}. Throws ParameterError naming
///  the key, value and what is allowed.
YarnSpec loadYarnSpec(const ParamValue& yarn, const ParamValue& presets);

/// Reads what makes a yarn, as in an entry of ~yarns, into `spec`: material, radius [m] | tex
/// [g/km] (+ packing_fraction [-]), weibull_modulus [-] or strength_cv [-], gauge_length [m],
/// seed (a fabric's warp and weft). Throws ParameterError naming the key.
void loadYarnMaking(const ParamValue& yarn, const ParamValue& presets, YarnSpec& spec);

}  // namespace ros_layer
}  // namespace yarn_tearing
