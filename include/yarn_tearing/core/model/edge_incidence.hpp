#pragma once

#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

/// Which edges meet at each vertex (compressed rows: vertex -> incident edges), for walking an
/// edge graph of any shape.
class EdgeIncidence {
 public:
  /// Rebuilds from the edge list; call whenever edges are added (breaking does not change it).
  void build(const EdgeSet& edges, std::size_t num_vertices);

  /// First of the edges incident to vertex `v`.
  const std::uint32_t* begin(std::uint32_t v) const { return edge_.data() + offset_[v]; }
  /// One past the last of the edges incident to vertex `v`.
  const std::uint32_t* end(std::uint32_t v) const { return edge_.data() + offset_[v + 1]; }

 private:
  std::vector<std::uint32_t> offset_;  ///< per vertex, where its edges start in edge_
  std::vector<std::uint32_t> edge_;    ///< incident edges, vertex by vertex
};

}  // namespace yarn_tearing
