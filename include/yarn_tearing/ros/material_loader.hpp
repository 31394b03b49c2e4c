#pragma once

#include "yarn_tearing/core/material/material.hpp"
#include "yarn_tearing/ros/param_value.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Reads a yarn's `material`: either the name of a preset in `presets` (the node's ~materials map,
/// loaded from config/materials.yaml) or an inline map {density [kg/m^3], rate_sensitivity
/// [-, per decade of strain rate] (optional, default 0), stress_strain: [[strain, Pa], ...]}; the
/// replaced key plastic_viscosity is accepted when 0.0 and refused otherwise. `presets` may be a
/// missing (invalid-typed) value when no presets were loaded. Throws ParameterError.
Material loadMaterial(const ParamValue& material, const ParamValue& presets);

}  // namespace ros_layer
}  // namespace yarn_tearing
