#pragma once

#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

/// The connected pieces of the vertex graph through the intact edges (union-find).
class ConnectedPieces {
 public:
  /// Groups `vertex_count` vertices by the intact edges of `edges`.
  void build(const EdgeSet& edges, std::size_t vertex_count);
  /// A representative vertex of v's piece (the same for every vertex of the piece).
  std::uint32_t root(std::uint32_t v);

 private:
  std::vector<std::uint32_t> parent_;  ///< union-find forest over the vertices
};

}  // namespace yarn_tearing
