#include "yarn_tearing/core/tearing/tearing.hpp"

#include <algorithm>
#include <limits>

#include "yarn_tearing/core/tearing/state_at_tear.hpp"

namespace yarn_tearing {
namespace {

double overstrain(const Scene& scene, std::size_t e) {
  const EdgeSet& edges = scene.edges;
  return edges.strain[e] / edges.breaking_strain[e];
}

/// c = sqrt(E / rho) of edge e's material [m/s]: how fast a tear's unloading runs through it.
double waveSpeed(const Scene& scene, std::size_t e) {
  return scene.yarns[scene.edges.yarn[e]].material.waveSpeed();
}

}  // namespace

bool Tearing::waiting(const Scene& scene, std::size_t e, double time) const {
  const std::uint32_t a = scene.edges.vertex_a[e];
  if (unloaded_at_.empty() || !(unloaded_at_[a] > time)) return false;
  // The straight distance is at most the way along the yarns, so an edge counts as reached no
  // later than the wave reaches it.
  const std::vector<Eigen::Vector3d>& x = scene.vertices.position;
  const double distance = std::min((x[a] - tear_point_[a]).norm(),
                                   (x[scene.edges.vertex_b[e]] - tear_point_[a]).norm());
  return distance > wave_speed_[a] * (time - torn_at_[a]);
}

const std::vector<std::uint32_t>& Tearing::collect(const Scene& scene, double time) {
  collected_.clear();
  const EdgeSet& edges = scene.edges;
  bool any = false;
  for (std::size_t e = 0; e < edges.size() && !any; ++e) {
    any = edges.intact(e) && overstrain(scene, e) >= 1.0 && !waiting(scene, e, time);
  }
  if (!any) return collected_;

  const std::size_t n = scene.vertices.size();
  pieces_.build(edges, n);
  best_of_piece_.assign(n, -1);
  best_ratio_.assign(n, 0.0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e) || waiting(scene, e, time)) continue;
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

void Tearing::apply(Scene& scene, const std::vector<Eigen::Vector3d>& start_velocity, double time,
                    std::vector<TearEvent>& events) {
  EdgeSet& edges = scene.edges;
  if (!collected_.empty()) startUnloading(scene, time);
  for (std::uint32_t e : collected_) {
    events.push_back(tearEventOf(scene, start_velocity, e, time));
    edges.broken[e] = 1;
    edges.tension[e] = 0.0;
    edges.spring_tension[e] = 0.0;
    edges.stress[e] = 0.0;
    edges.strain_rate[e] = 0.0;
  }
  collected_.clear();
}

Tearing Tearing::restrictedTo(const std::vector<std::uint32_t>& vertices) const {
  Tearing restricted;
  restricted.unloading_end_ = unloading_end_;
  if (unloaded_at_.empty()) return restricted;
  for (std::uint32_t v : vertices) {
    restricted.unloaded_at_.push_back(unloaded_at_[v]);
    restricted.torn_at_.push_back(torn_at_[v]);
    restricted.tear_point_.push_back(tear_point_[v]);
    restricted.wave_speed_.push_back(wave_speed_[v]);
  }
  return restricted;
}

void Tearing::startUnloading(const Scene& scene, double time) {
  // Each torn piece unloads by an elastic wave from the tear, at c = sqrt(E / rho) of the torn
  // edge's material; it takes about the piece's extent over c (the diagonal of its box: a taut
  // yarn's length, a fabric's width, not the sum of its segments) to have crossed it.
  const EdgeSet& edges = scene.edges;
  const std::vector<Eigen::Vector3d>& position = scene.vertices.position;
  const std::size_t n = scene.vertices.size();
  const double infinite = std::numeric_limits<double>::infinity();
  box_min_.assign(n, Eigen::Vector3d::Constant(infinite));
  box_max_.assign(n, Eigen::Vector3d::Constant(-infinite));
  for (std::size_t v = 0; v < n; ++v) {
    const std::uint32_t root = pieces_.root(static_cast<std::uint32_t>(v));
    box_min_[root] = box_min_[root].cwiseMin(position[v]);
    box_max_[root] = box_max_[root].cwiseMax(position[v]);
  }
  unloading_until_.assign(n, -1.0);
  tear_of_piece_.assign(n, 0);
  for (std::uint32_t e : collected_) {
    const std::uint32_t root = pieces_.root(edges.vertex_a[e]);
    const double speed = waveSpeed(scene, e);
    unloading_until_[root] = time + (box_max_[root] - box_min_[root]).norm() / speed;
    unloading_end_ = std::max(unloading_end_, unloading_until_[root]);
    tear_of_piece_[root] = e;
  }
  unloaded_at_.resize(n, -1.0);
  torn_at_.resize(n, -1.0);
  tear_point_.resize(n, Eigen::Vector3d::Zero());
  wave_speed_.resize(n, 0.0);
  for (std::size_t v = 0; v < n; ++v) {
    const std::uint32_t root = pieces_.root(static_cast<std::uint32_t>(v));
    if (!(unloading_until_[root] > 0.0)) continue;
    const std::uint32_t e = tear_of_piece_[root];
    unloaded_at_[v] = unloading_until_[root];
    torn_at_[v] = time;
    tear_point_[v] = 0.5 * (position[edges.vertex_a[e]] + position[edges.vertex_b[e]]);
    wave_speed_[v] = waveSpeed(scene, e);
  }
}

}  // namespace yarn_tearing
