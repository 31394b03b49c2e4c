#include "yarn_tearing/core/tearing.hpp"

#include <algorithm>

#include "yarn_tearing/core/state_at_tear.hpp"

namespace yarn_tearing {
namespace {

double overstrain(const Scene& scene, std::size_t e) {
  const EdgeSet& edges = scene.edges;
  return edges.strain[e] / edges.breaking_strain[e];
}

}  // namespace

const std::vector<std::uint32_t>& Tearing::collect(const Scene& scene) {
  collected_.clear();
  const EdgeSet& edges = scene.edges;
  bool any = false;
  for (std::size_t e = 0; e < edges.size() && !any; ++e) {
    any = edges.intact(e) && overstrain(scene, e) >= 1.0;
  }
  if (!any) return collected_;

  const std::size_t n = scene.vertices.size();
  pieces_.build(edges, n);
  best_of_piece_.assign(n, -1);
  best_ratio_.assign(n, 0.0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e)) continue;
    const double ratio = overstrain(scene, e);
    const std::uint32_t root = pieces_.root(edges.vertex_a[e]);
    if (ratio >= 1.0 && ratio > best_ratio_[root]) {
      best_ratio_[root] = ratio;
      best_of_piece_[root] = static_cast<std::int64_t>(e);
    }
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (best_of_piece_[v] >= 0) collected_.push_back(static_cast<std::uint32_t>(best_of_piece_[v]));
  }
  std::sort(collected_.begin(), collected_.end());
  return collected_;
}

void Tearing::apply(Scene& scene, double time, double time_step, std::vector<TearEvent>& events) {
  EdgeSet& edges = scene.edges;
  for (std::uint32_t e : collected_) {
    events.push_back(tearEventOf(scene, e, time, time_step));
    edges.broken[e] = 1;
    edges.tension[e] = 0.0;
    edges.spring_tension[e] = 0.0;
    edges.stress[e] = 0.0;
    edges.strain_rate[e] = 0.0;
  }
  collected_.clear();
}

}  // namespace yarn_tearing
