#include "yarn_tearing/core/model/edge_chains.hpp"

#include <algorithm>

namespace yarn_tearing {

void EdgeChains::build(const EdgeSet& edges, const EdgeIncidence& incidence) {
  const std::size_t q = edges.size();
  next_at_a_.assign(q, kNoVertex);
  next_at_b_.assign(q, kNoVertex);
  std::uint32_t num_vertices = 0;
  for (std::size_t e = 0; e < q; ++e) {
    num_vertices = std::max({num_vertices, edges.vertex_a[e] + 1, edges.vertex_b[e] + 1});
  }
  for (std::uint32_t v = 0; v < num_vertices; ++v) {
    for (const std::uint32_t* e = incidence.begin(v); e != incidence.end(v); ++e) {
      // The continuation of *e at v: the one other edge of its yarn there, if it is the only one.
      std::uint32_t other = kNoVertex;
      int same_yarn = 0;
      for (const std::uint32_t* f = incidence.begin(v); f != incidence.end(v); ++f) {
        if (*f == *e || edges.yarn[*f] != edges.yarn[*e]) continue;
        other = *f;
        ++same_yarn;
      }
      if (same_yarn != 1) continue;
      (edges.vertex_a[*e] == v ? next_at_a_ : next_at_b_)[*e] = other;
    }
  }
  order_.clear();
  joint_.clear();
  placed_.assign(q, 0);
  // Walks the chain from edge `start` away from vertex `from`'s side.
  const auto walk = [&](std::uint32_t start, bool leave_at_b) {
    std::uint32_t e = start;
    while (!placed_[e]) {
      placed_[e] = 1;
      order_.push_back(e);
      const std::uint32_t v = leave_at_b ? edges.vertex_b[e] : edges.vertex_a[e];
      const std::uint32_t next = leave_at_b ? next_at_b_[e] : next_at_a_[e];
      const bool goes_on = next != kNoVertex && !placed_[next];
      joint_.push_back(goes_on ? v : kNoVertex);
      if (!goes_on) return;
      leave_at_b = edges.vertex_a[next] == v;
      e = next;
    }
  };
  // Chains with an end first (from the end), then closed loops (from their lowest edge).
  for (std::uint32_t e = 0; e < q; ++e) {
    if (placed_[e]) continue;
    if (next_at_a_[e] == kNoVertex) {
      walk(e, true);
    } else if (next_at_b_[e] == kNoVertex) {
      walk(e, false);
    }
  }
  for (std::uint32_t e = 0; e < q; ++e) {
    if (!placed_[e]) walk(e, true);
  }
}

}  // namespace yarn_tearing
