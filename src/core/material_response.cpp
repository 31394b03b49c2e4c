#include "yarn_tearing/core/material_response.hpp"

#include <algorithm>
#include <cmath>

namespace yarn_tearing {
namespace {

/// Plastic strain [-] after one step at `stress` [Pa]. Flow stops at the edge's breaking point
/// (where its curve reaches `breaking_strain`): past it the edge tears instead (stage 6), and an
/// edge whose piece tore elsewhere in the same step, so that its load dropped, keeps no more
/// plastic strain than the breaking point leaves.
double updatedPlasticStrain(double current, double stress, double breaking_strain,
                            const Material& material, double time_step) {
  if (stress <= material.curve.yieldStress()) return current;
  const double flow_stress = std::min(stress, material.curve.stressAtStrain(breaking_strain));
  const double target = material.curve.plasticStrainAtStress(flow_stress);
  if (!(target > current)) return current;
  if (material.plastic_viscosity <= 0.0) return target;
  const double rate = material.curve.youngsModulus() / material.plastic_viscosity;  // [1/s]
  return current + (target - current) * -std::expm1(-rate * time_step);
}

}  // namespace

void updateMaterialResponse(const std::vector<Yarn>& yarns, double time_step, EdgeSet& edges) {
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e)) continue;
    const Material& material = yarns[edges.yarn[e]].material;
    const double stress = edges.tension[e] / edges.area[e];
    edges.stress[e] = stress;
    const double load = std::max(stress, 0.0);
    const double breaking_strain = material.curve.breakingStrain() * edges.strength_factor[e];
    edges.plastic_strain[e] =
        updatedPlasticStrain(edges.plastic_strain[e], load, breaking_strain, material, time_step);
    const double elastic = load / material.curve.youngsModulus();
    const double strain = edges.plastic_strain[e] + elastic;
    edges.strain_rate[e] = (strain - edges.strain[e]) / time_step;
    edges.strain[e] = strain;
    edges.rest_length[e] = edges.original_rest_length[e] * (1.0 + edges.plastic_strain[e]);
    edges.strain_limit[e] = elastic / (1.0 + edges.plastic_strain[e]);
  }
}

}  // namespace yarn_tearing
