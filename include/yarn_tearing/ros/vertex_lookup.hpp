#pragma once

#include <cstdint>
#include <string>

#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Which vertex of a yarn or fabric a message (AppliedForce, Grasp) addresses.
struct VertexAddress {
  /// Vertex index, negative counting from the end (a fabric's: row * ends + column) [-].
  int vertex = 0;
  /// True: a fabric's vertex given by `row` and `column` (`vertex` ignored) [-].
  bool by_row_and_column = false;
  int row = 0;     ///< a fabric's row (weft pick), negative counting from the last [-]
  int column = 0;  ///< a fabric's column (warp end), negative counting from the last [-]

  /// The address of a message with the fields `vertex`, `by_row_and_column`, `row`, `column`.
  template <class Message>
  static VertexAddress of(const Message& msg) {
    return VertexAddress{msg.vertex, msg.by_row_and_column != 0, msg.row, msg.column};
  }
  /// "vertex 3" or "vertex (row 2, column -1)", for warnings.
  std::string describe() const;
};

/// Global vertex id of the vertex at `address` of the yarn or fabric named `yarn`. Throws
/// InputRejected naming the unknown name (and the known ones), the allowed index, row or column
/// range, or a row and column given for a yarn.
std::uint32_t lookupVertex(const Scene& scene, const std::string& yarn,
                           const VertexAddress& address);

}  // namespace ros_layer
}  // namespace yarn_tearing
