#include "yarn_tearing/core/model/edge_incidence.hpp"

namespace yarn_tearing {

void EdgeIncidence::build(const EdgeSet& edges, std::size_t num_vertices) {
  offset_.assign(num_vertices + 1, 0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    ++offset_[edges.vertex_a[e] + 1];
    ++offset_[edges.vertex_b[e] + 1];
  }
  for (std::size_t v = 0; v < num_vertices; ++v) offset_[v + 1] += offset_[v];
  edge_.assign(offset_.back(), 0);
  std::vector<std::uint32_t> fill(offset_.begin(), offset_.end() - 1);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    edge_[fill[edges.vertex_a[e]]++] = static_cast<std::uint32_t>(e);
    edge_[fill[edges.vertex_b[e]]++] = static_cast<std::uint32_t>(e);
  }
}

}  // namespace yarn_tearing
