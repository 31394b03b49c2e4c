#pragma once

#include <vector>

#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Per vertex of `scene`, the breaking forces [N] of the edges that meet there, summed:
/// A_e f_e sigma_b of each edge e at the vertex (area, strength factor, its yarn's breaking
/// stress), torn or not. A force that many times past it tears the vertex out within a step
/// whatever it is; the applied-force bound is a multiple of it (input_bounds).
std::vector<double> vertexBreakingForces(const Scene& scene);

}  // namespace ros_layer
}  // namespace yarn_tearing
