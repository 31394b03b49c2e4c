#include "yarn_tearing/ros/vertex_lookup.hpp"

#include <stdexcept>

#include "yarn_tearing/ros/clipped_text.hpp"
#include "yarn_tearing/ros/input_rejected.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr std::size_t kMaxKnownList = 200;  ///< [characters] of the known yarn names quoted

}  // namespace

std::uint32_t lookupVertex(const Scene& scene, const std::string& yarn, int vertex) {
  const int fabric = scene.findFabric(yarn);
  if (fabric >= 0) {
    const auto& f = scene.fabrics[static_cast<std::size_t>(fabric)];
    const auto n = static_cast<int>(f.numVertices());
    if (vertex < -n || vertex >= n) {
      throw InputRejected(RefusalReason::kVertexOutOfRange,
                          "vertex " + std::to_string(vertex) + " of fabric '" + clipped(yarn) +
                              "' out of range [" + std::to_string(-n) + ", " +
                              std::to_string(n - 1) + "] (row * " + std::to_string(f.ends) +
                              " + column)");
    }
    return f.first_vertex + static_cast<std::uint32_t>(vertex < 0 ? n + vertex : vertex);
  }
  const int index = scene.findYarn(yarn);
  if (index < 0) {
    std::string known;
    for (const Fabric& f : scene.fabrics) known += (known.empty() ? "" : ", ") + clipped(f.name);
    for (const Yarn& y : scene.yarns) {
      if (y.fabric >= 0) continue;
      known += (known.empty() ? "" : ", ") + clipped(y.name);
      if (known.size() > kMaxKnownList) {
        known += ", ...";
        break;
      }
    }
    throw InputRejected(RefusalReason::kUnknownYarn,
                        "unknown yarn '" + clipped(yarn) + "' (known: " + known + ")");
  }
  const auto n = static_cast<int>(scene.yarns[static_cast<std::size_t>(index)].num_vertices);
  if (vertex < -n || vertex >= n) {
    throw InputRejected(RefusalReason::kVertexOutOfRange,
                        "vertex " + std::to_string(vertex) + " of yarn '" + clipped(yarn) +
                            "' out of range [" + std::to_string(-n) + ", " + std::to_string(n - 1) +
                            "]");
  }
  return scene.globalVertex(static_cast<std::size_t>(index), vertex);
}

}  // namespace ros_layer
}  // namespace yarn_tearing
