#pragma once

#include "yarn_tearing/core/model/fabric_spec.hpp"
#include "yarn_tearing/ros/param_value.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Reads one entry of ~fabrics (doc/node.md, "Fabrics"):
/// {name, weave ('plain'), warp_length [m], weft_length [m], ends, picks, origin [m],
///  warp_direction, weft_direction, warp {yarn keys of loadYarnMaking}, weft {...},
///  warp_crimp [-], weft_crimp [-], shear_rigidity [N/m], pinned [[row, column], ...],
///  pinned_sides [first_row | last_row | first_column | last_column, ...],
///  slits [{family: warp | weft, first_yarn, last_yarn, segment}, ...]}.
/// Throws ParameterError naming the key, its value and what is allowed.
FabricSpec loadFabricSpec(const ParamValue& fabric, const ParamValue& presets);

}  // namespace ros_layer
}  // namespace yarn_tearing
