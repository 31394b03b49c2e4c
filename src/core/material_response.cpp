#include "yarn_tearing/core/material_response.hpp"

#include <algorithm>
#include <cmath>

namespace yarn_tearing {
namespace {

double updatedPlasticStrain(double current, double stress, const Material& material,
                            double time_step) {
  const double target = material.curve.plasticStrainAtStress(stress);
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
    edges.plastic_strain[e] =
        updatedPlasticStrain(edges.plastic_strain[e], load, material, time_step);
    const double elastic = load / material.curve.youngsModulus();
    const double strain = edges.plastic_strain[e] + elastic;
    edges.strain_rate[e] = (strain - edges.strain[e]) / time_step;
    edges.strain[e] = strain;
    edges.rest_length[e] = edges.original_rest_length[e] * (1.0 + edges.plastic_strain[e]);
    edges.strain_limit[e] = elastic / (1.0 + edges.plastic_strain[e]);
  }
}

}  // namespace yarn_tearing
