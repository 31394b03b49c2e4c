#include "yarn_tearing/core/simulation/nonfinite_recovery.hpp"

#include <cmath>

namespace yarn_tearing {
namespace {

/// Whether `count` values from `values` are all finite: 0 x is 0 for each finite x and NaN for
/// an infinite or NaN one, and a sum with a NaN is NaN (a vectorized sum, no branch per value).
bool allFinite(const double* values, std::size_t count) {
  return (Eigen::Map<const Eigen::ArrayXd>(values, static_cast<Eigen::Index>(count)) * 0.0).sum() ==
         0.0;
}

bool allFinite(double value) { return std::isfinite(value); }
bool allFinite(const Eigen::Vector3d& value) { return value.allFinite(); }

/// Marks in `bad` (one flag per yarn of `yarn_count`, left empty until a value is found) the
/// yarn (`yarn_of`, per element) of each non-finite element of `values` (doubles or Vector3d,
/// three packed doubles); screens the whole array at once first.
template <typename Value>
void markNonFinite(const std::vector<Value>& values, const std::vector<std::uint32_t>& yarn_of,
                   std::size_t yarn_count, std::vector<std::uint8_t>& bad) {
  static_assert(sizeof(Value) % sizeof(double) == 0);
  if (values.empty() || allFinite(reinterpret_cast<const double*>(values.data()),
                                  values.size() * (sizeof(Value) / sizeof(double)))) {
    return;
  }
  bad.resize(yarn_count, 0);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!allFinite(values[i])) bad[yarn_of[i]] = 1;
  }
}

}  // namespace

std::vector<std::uint32_t> nonFiniteYarns(const Scene& scene,
                                          const std::vector<Eigen::Vector3d>& support_force) {
  std::vector<std::uint8_t> bad;  // per yarn, allocated at the first non-finite value
  const std::size_t yarn_count = scene.yarns.size();
  const VertexSet& vertices = scene.vertices;
  const EdgeSet& edges = scene.edges;
  markNonFinite(vertices.position, vertices.yarn, yarn_count, bad);
  markNonFinite(vertices.velocity, vertices.yarn, yarn_count, bad);
  markNonFinite(support_force, vertices.yarn, yarn_count, bad);
  for (const std::vector<double>* values :
       {&edges.rest_length, &edges.strain_limit, &edges.tension, &edges.spring_tension,
        &edges.stress, &edges.strain, &edges.plastic_strain, &edges.strain_rate}) {
    markNonFinite(*values, edges.yarn, yarn_count, bad);
  }
  std::vector<std::uint32_t> yarns;
  if (bad.empty()) return yarns;
  // A fabric is restored whole: both of its groups (its vertices belong to the warp group).
  for (const Fabric& fabric : scene.fabrics) {
    if (bad[fabric.warp_group] || bad[fabric.weft_group]) {
      bad[fabric.warp_group] = 1;
      bad[fabric.weft_group] = 1;
    }
  }
  for (std::size_t y = 0; y < bad.size(); ++y) {
    if (bad[y]) yarns.push_back(static_cast<std::uint32_t>(y));
  }
  return yarns;
}

void restoreYarn(const Scene& initial, std::uint32_t yarn, Scene& scene) {
  VertexSet& vertices = scene.vertices;
  const VertexSet& start = initial.vertices;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (vertices.yarn[v] != yarn) continue;
    vertices.position[v] = start.position[v];
    vertices.velocity[v] = start.velocity[v];
    vertices.motion[v] = start.motion[v];
    vertices.applied_force[v] = start.applied_force[v];
    vertices.kinematic_target[v] = start.kinematic_target[v];
  }
  EdgeSet& edges = scene.edges;
  const EdgeSet& unloaded = initial.edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (edges.yarn[e] != yarn) continue;
    edges.rest_length[e] = unloaded.rest_length[e];
    edges.strain_limit[e] = unloaded.strain_limit[e];
    edges.plastic_strain[e] = unloaded.plastic_strain[e];
    edges.tension[e] = unloaded.tension[e];
    edges.spring_tension[e] = unloaded.spring_tension[e];
    edges.stress[e] = unloaded.stress[e];
    edges.strain[e] = unloaded.strain[e];
    edges.strain_rate[e] = unloaded.strain_rate[e];
    edges.broken[e] = unloaded.broken[e];
  }
}

}  // namespace yarn_tearing
