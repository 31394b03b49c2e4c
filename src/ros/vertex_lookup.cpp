#include "yarn_tearing/ros/vertex_lookup.hpp"

#include <stdexcept>

#include "yarn_tearing/ros/input_rejected.hpp"

namespace yarn_tearing {
namespace ros_layer {

std::uint32_t lookupVertex(const Scene& scene, const std::string& yarn, int vertex) {
  const int index = scene.findYarn(yarn);
  if (index < 0) {
    std::string known;
    for (const Yarn& y : scene.yarns) {
      known += (known.empty() ? "" : ", ") + y.name;
    }
    throw InputRejected("unknown yarn '" + yarn + "' (known: " + known + ")");
  }
  try {
    return scene.globalVertex(static_cast<std::size_t>(index), vertex);
  } catch (const std::out_of_range& e) {
    throw InputRejected(e.what());
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
