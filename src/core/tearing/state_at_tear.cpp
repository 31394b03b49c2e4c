#include "yarn_tearing/core/tearing/state_at_tear.hpp"

#include <algorithm>

namespace yarn_tearing {

TearEvent tearEventOf(const Scene& scene, const std::vector<Eigen::Vector3d>& start_velocity,
                      std::size_t edge, double time) {
  const EdgeSet& edges = scene.edges;
  const Yarn& yarn = scene.yarns[edges.yarn[edge]];
  const StressStrainCurve& curve = yarn.material.curve;
  const Eigen::Vector3d& xa = scene.vertices.position[edges.vertex_a[edge]];
  const Eigen::Vector3d& xb = scene.vertices.position[edges.vertex_b[edge]];

  TearEvent event;
  event.yarn = edges.yarn[edge];
  event.edge = static_cast<std::uint32_t>(edge) - yarn.first_edge;
  event.vertex_a = edges.vertex_a[edge] - yarn.first_vertex;
  event.vertex_b = edges.vertex_b[edge] - yarn.first_vertex;
  event.fabric = yarn.fabric;
  if (yarn.fabric >= 0) event.segment = scene.fabricSegmentOf(edge);
  event.position = 0.5 * (xa + xb);
  event.time = time;

  const double breaking_strain = edges.breaking_strain[edge];
  const double length_strain = (xb - xa).norm() / edges.original_rest_length[edge] - 1.0;
  event.strain = std::min(length_strain, breaking_strain);
  event.plastic_strain = edges.plastic_strain[edge];
  const double elastic_stress = curve.youngsModulus() * (event.strain - event.plastic_strain);
  // The curve at the edge's loading rate: the material's with its stresses times f.
  const double carried =
      edges.rate_factor[edge] *
      std::max(0.0, std::min(elastic_stress, curve.stressAtStrain(event.strain)));
  event.stress = std::max(0.0, std::min(edges.stress[edge], carried));
  event.tension = event.stress * edges.area[edge];
  // The rate of the geometric strain |x_b - x_a| / L0 - 1 as the step began: the ends' relative
  // velocity along the edge over L0 (a free end's velocity is its displacement over the previous
  // step, a grasp's its target's). The step that tears the edge may end at its breaking length,
  // which stops the stretch part way; the rate it was loaded at is the one it entered with.
  const Eigen::Vector3d axis = (xb - xa).normalized();
  const Eigen::Vector3d relative =
      start_velocity[edges.vertex_b[edge]] - start_velocity[edges.vertex_a[edge]];
  event.strain_rate =
      axis.allFinite() ? axis.dot(relative) / edges.original_rest_length[edge] : 0.0;
  return event;
}

}  // namespace yarn_tearing
