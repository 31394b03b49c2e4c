#include "yarn_tearing/core/model/connected_pieces.hpp"

namespace yarn_tearing {

void ConnectedPieces::build(const EdgeSet& edges, std::size_t vertex_count) {
  parent_.resize(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) parent_[v] = static_cast<std::uint32_t>(v);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (edges.intact(e)) parent_[root(edges.vertex_a[e])] = root(edges.vertex_b[e]);
  }
}

std::uint32_t ConnectedPieces::root(std::uint32_t v) {
  while (parent_[v] != v) {
    parent_[v] = parent_[parent_[v]];  // path halving
    v = parent_[v];
  }
  return v;
}

}  // namespace yarn_tearing
