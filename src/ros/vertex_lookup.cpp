#include "yarn_tearing/ros/vertex_lookup.hpp"

#include <stdexcept>

#include "yarn_tearing/ros/clipped_text.hpp"
#include "yarn_tearing/ros/input_rejected.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr std::size_t kMaxKnownList = 200;  ///< [characters] of the known yarn names quoted

/// `index` (negative counts from the end) within [0, count), or InputRejected naming `what` of
/// `owner` and the range allowed.
std::uint32_t indexWithin(int index, int count, const std::string& what, const std::string& owner,
                          const std::string& hint = "") {
  if (index < -count || index >= count) {
    throw InputRejected(RefusalReason::kVertexOutOfRange,
                        what + " " + std::to_string(index) + " of " + owner + " out of range [" +
                            std::to_string(-count) + ", " + std::to_string(count - 1) + "]" + hint);
  }
  return static_cast<std::uint32_t>(index < 0 ? count + index : index);
}

std::string knownNames(const Scene& scene) {
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
  return known;
}

std::uint32_t fabricVertex(const Fabric& f, const VertexAddress& address) {
  const std::string owner = "fabric '" + clipped(f.name) + "'";
  if (address.by_row_and_column) {
    const std::uint32_t row = indexWithin(address.row, static_cast<int>(f.picks), "row", owner);
    const std::uint32_t column =
        indexWithin(address.column, static_cast<int>(f.ends), "column", owner);
    return f.vertex(row, column);
  }
  const std::string hint = " (row * " + std::to_string(f.ends) + " + column)";
  return f.first_vertex +
         indexWithin(address.vertex, static_cast<int>(f.numVertices()), "vertex", owner, hint);
}

}  // namespace

std::string VertexAddress::describe() const {
  if (!by_row_and_column) return "vertex " + std::to_string(vertex);
  return "vertex (row " + std::to_string(row) + ", column " + std::to_string(column) + ")";
}

std::uint32_t lookupVertex(const Scene& scene, const std::string& yarn,
                           const VertexAddress& address) {
  const int fabric = scene.findFabric(yarn);
  if (fabric >= 0) return fabricVertex(scene.fabrics[static_cast<std::size_t>(fabric)], address);
  const int index = scene.findYarn(yarn);
  if (index < 0) {
    throw InputRejected(RefusalReason::kUnknownYarn,
                        "unknown yarn '" + clipped(yarn) + "' (known: " + knownNames(scene) + ")");
  }
  if (address.by_row_and_column) {
    throw InputRejected(RefusalReason::kVertexOutOfRange,
                        "row and column address a fabric's vertex; '" + clipped(yarn) +
                            "' is a yarn (give by_row_and_column false and its vertex)");
  }
  const Yarn& y = scene.yarns[static_cast<std::size_t>(index)];
  const std::uint32_t vertex = indexWithin(address.vertex, static_cast<int>(y.num_vertices),
                                           "vertex", "yarn '" + clipped(yarn) + "'");
  return scene.globalVertex(static_cast<std::size_t>(index), static_cast<int>(vertex));
}

}  // namespace ros_layer
}  // namespace yarn_tearing
