#include "yarn_tearing/core/simulation/nonfinite_recovery.hpp"

#include <cmath>

namespace yarn_tearing {
namespace {

bool edgeIsFinite(const EdgeSet& edges, std::size_t e) {
  return std::isfinite(edges.rest_length[e]) && std::isfinite(edges.strain_limit[e]) &&
         std::isfinite(edges.tension[e]) && std::isfinite(edges.spring_tension[e]) &&
         std::isfinite(edges.stress[e]) && std::isfinite(edges.strain[e]) &&
         std::isfinite(edges.plastic_strain[e]) && std::isfinite(edges.strain_rate[e]);
}

/// Whether `count` values from `values` are all finite: 0 x is 0 for each finite x and NaN for
/// an infinite or NaN one, and a sum with a NaN is NaN (a vectorized sum, no branch per value).
bool allFinite(const double* values, std::size_t count) {
  return (Eigen::Map<const Eigen::ArrayXd>(values, static_cast<Eigen::Index>(count)) * 0.0).sum() ==
         0.0;
}

bool allFinite(const std::vector<double>& values) {
  return allFinite(values.data(), values.size());
}

bool allFinite(const std::vector<Eigen::Vector3d>& values) {
  // A Vector3d is three packed doubles.
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double));
  return values.empty() || allFinite(values.front().data(), 3 * values.size());
}

/// Whether every value nonFiniteYarns() checks is finite, array by array: the vectorized
/// screen of the common case, before the search for the yarns of a non-finite one.
bool sceneIsFinite(const Scene& scene, const std::vector<Eigen::Vector3d>& support_force) {
  const VertexSet& vertices = scene.vertices;
  const EdgeSet& edges = scene.edges;
  return allFinite(vertices.position) && allFinite(vertices.velocity) && allFinite(support_force) &&
         allFinite(edges.rest_length) && allFinite(edges.strain_limit) &&
         allFinite(edges.tension) && allFinite(edges.spring_tension) && allFinite(edges.stress) &&
         allFinite(edges.strain) && allFinite(edges.plastic_strain) && allFinite(edges.strain_rate);
}

}  // namespace

std::vector<std::uint32_t> nonFiniteYarns(const Scene& scene,
                                          const std::vector<Eigen::Vector3d>& support_force) {
  if (sceneIsFinite(scene, support_force)) return {};
  std::vector<std::uint8_t> bad(scene.yarns.size(), 0);
  bool any = false;
  const VertexSet& vertices = scene.vertices;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (!vertices.position[v].allFinite() || !vertices.velocity[v].allFinite() ||
        !support_force[v].allFinite()) {
      bad[vertices.yarn[v]] = 1;
      any = true;
    }
  }
  const EdgeSet& edges = scene.edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edgeIsFinite(edges, e)) {
      bad[edges.yarn[e]] = 1;
      any = true;
    }
  }
  std::vector<std::uint32_t> yarns;
  if (!any) return yarns;
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
