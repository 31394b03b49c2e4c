#pragma once

#include <cstdint>
#include <string>

#include "yarn_tearing/core/scene.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Global vertex id of vertex `vertex` (negative counts from the end) of the yarn or fabric named
/// `yarn` (a fabric's vertex index is row * ends + column). Throws InputRejected naming the
/// unknown name (and the known ones) or the allowed index range.
std::uint32_t lookupVertex(const Scene& scene, const std::string& yarn, int vertex);

}  // namespace ros_layer
}  // namespace yarn_tearing
