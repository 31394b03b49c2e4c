#include "yarn_tearing/core/projection/edge_stretch_limits.hpp"

#include <algorithm>

namespace yarn_tearing {

double stabilitySpringConstant(const VertexSet& vertices, std::uint32_t a, std::uint32_t b,
                               const SimulationParameters& p) {
  double lighter = 0.0;
  if (!vertices.isSupport(a)) lighter = vertices.mass[a];
  if (!vertices.isSupport(b)) {
    lighter = lighter > 0.0 ? std::min(lighter, vertices.mass[b]) : vertices.mass[b];
  }
  return p.soft_spring_ratio * lighter / (p.time_step * p.time_step);
}

void computeStretchLimits(const Scene& scene, const SimulationParameters& parameters,
                          EdgeStretchLimits& limits) {
  const EdgeSet& edges = scene.edges;
  limits.compliance.resize(edges.size());
  limits.soft_spring.resize(edges.size());
  limits.max_stretch.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const StressStrainCurve& curve = scene.yarns[edges.yarn[e]].material.curve;
    const double original = edges.original_rest_length[e];
    const double compliance =
        original / (curve.youngsModulus() * edges.rate_factor[e] * edges.area[e]);
    limits.compliance[e] = compliance;
    limits.soft_spring[e] = std::min(
        stabilitySpringConstant(scene.vertices, edges.vertex_a[e], edges.vertex_b[e], parameters),
        EdgeStretchLimits::kSoftSpringShare / compliance);
    const double breaking_length = original * (1.0 + edges.breaking_strain[e]);
    limits.max_stretch[e] = std::max(breaking_length - edges.rest_length[e], 0.0);
  }
}

}  // namespace yarn_tearing
