#include "yarn_tearing/core/edge_stretch_limits.hpp"

#include <algorithm>

namespace yarn_tearing {

void computeStretchLimits(const Scene& scene, EdgeStretchLimits& limits) {
  const EdgeSet& edges = scene.edges;
  limits.compliance.resize(edges.size());
  limits.max_stretch.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const StressStrainCurve& curve = scene.yarns[edges.yarn[e]].material.curve;
    const double original = edges.original_rest_length[e];
    limits.compliance[e] = original / (curve.youngsModulus() * edges.area[e]);
    const double breaking_length =
        original * (1.0 + curve.breakingStrain() * edges.strength_factor[e]);
    limits.max_stretch[e] = std::max(breaking_length - edges.rest_length[e], 0.0);
  }
}

}  // namespace yarn_tearing
