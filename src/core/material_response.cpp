#include "yarn_tearing/core/material_response.hpp"

#include <algorithm>
#include <cmath>

namespace yarn_tearing {
namespace {

/// Stress [Pa] that the edge's geometric strain demands when the constraint could not hold it,
/// or 0 when the constraint holds.
double displacementStress(const EdgeSet& edges, std::size_t e, const StressStrainCurve& curve,
                          const std::vector<Eigen::Vector3d>& position, double tolerance) {
  const double length = (position[edges.vertex_b[e]] - position[edges.vertex_a[e]]).norm();
  const double limit = edges.rest_length[e] * (1.0 + edges.strain_limit[e]);
  if (!(length > limit * (1.0 + 10.0 * tolerance))) return 0.0;
  const double total_strain = length / edges.original_rest_length[e] - 1.0;
  const double elastic_trial = curve.youngsModulus() * (total_strain - edges.plastic_strain[e]);
  return std::min(elastic_trial, curve.stressAtStrain(total_strain));
}

double updatedPlasticStrain(double current, double stress, const Material& material,
                            double time_step) {
  const double target = material.curve.plasticStrainAtStress(stress);
  if (!(target > current)) return current;
  if (material.plastic_viscosity <= 0.0) return target;
  const double rate = material.curve.youngsModulus() / material.plastic_viscosity;  // [1/s]
  return current + (target - current) * -std::expm1(-rate * time_step);
}

}  // namespace

void updateMaterialResponse(const std::vector<Yarn>& yarns,
                            const std::vector<Eigen::Vector3d>& position, double time_step,
                            double constraint_tolerance, EdgeSet& edges) {
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e)) continue;
    const Material& material = yarns[edges.yarn[e]].material;
    const double modulus = material.curve.youngsModulus();
    const double forced =
        displacementStress(edges, e, material.curve, position, constraint_tolerance);
    double stress = edges.tension[e] / edges.area[e];
    if (forced > stress) {
      stress = forced;
      edges.tension[e] = stress * edges.area[e];
    }
    edges.stress[e] = stress;
    const double load = std::max(stress, 0.0);
    edges.plastic_strain[e] = updatedPlasticStrain(edges.plastic_strain[e], load, material,
                                                   time_step);
    const double elastic = load / modulus;
    const double strain = edges.plastic_strain[e] + elastic;
    edges.strain_rate[e] = (strain - edges.strain[e]) / time_step;
    edges.strain[e] = strain;
    edges.rest_length[e] = edges.original_rest_length[e] * (1.0 + edges.plastic_strain[e]);
    edges.strain_limit[e] = elastic / (1.0 + edges.plastic_strain[e]);
  }
}

}  // namespace yarn_tearing
