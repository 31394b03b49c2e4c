#include "yarn_tearing/core/material/material_response.hpp"

#include <algorithm>

#include "yarn_tearing/core/material/rate_dependence.hpp"

namespace yarn_tearing {
namespace {

/// Plastic strain [-] after one step at `stress` [Pa] on the reference curve. Flow stops at the
/// edge's breaking point (where its curve reaches `breaking_strain`): past it the edge tears
/// instead (stage 6), and an edge whose piece tore elsewhere in the same step, so that its load
/// dropped, keeps no more plastic strain than the breaking point leaves.
double updatedPlasticStrain(double current, double stress, double breaking_strain,
                            const StressStrainCurve& curve) {
  if (stress <= curve.yieldStress()) return current;
  const double flow_stress = std::min(stress, curve.stressAtStrain(breaking_strain));
  return std::max(current, curve.plasticStrainAtStress(flow_stress));
}

/// Advances edge e's loading clock and sets the rate factor the next step uses: the loading rate
/// is the strain gained since the edge last went from slack to taut over the time since, which
/// a constant-rate test reads exactly and which changes slowly enough not to feed back.
void updateRateFactor(const Material& material, double time_step, double previous_strain,
                      bool loaded, std::size_t e, EdgeSet& edges) {
  if (material.rate_sensitivity == 0.0) return;  // f stays 1
  if (!loaded) {
    edges.loading_time[e] = 0.0;
    edges.rate_factor[e] = 1.0;
    return;
  }
  if (edges.loading_time[e] == 0.0) edges.loading_start_strain[e] = previous_strain;
  edges.loading_time[e] += time_step;
  // An edge held at its breaking length by the stop past it tears in this step: the force the
  // stop takes on is no strain the edge was loaded at.
  const double strain = std::min(edges.strain[e], edges.breaking_strain[e]);
  const double rate = (strain - edges.loading_start_strain[e]) / edges.loading_time[e];
  edges.rate_factor[e] = RateDependence::stressFactor(material.rate_sensitivity, rate);
}

}  // namespace

void updateMaterialResponse(const std::vector<Yarn>& yarns, double time_step, EdgeSet& edges) {
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e)) continue;
    const Material& material = yarns[edges.yarn[e]].material;
    const StressStrainCurve& curve = material.curve;
    const double stress = edges.tension[e] / edges.area[e];
    edges.stress[e] = stress;
    // The curve at this edge's rate is the reference curve with its stresses times f.
    const double load = std::max(stress, 0.0) / edges.rate_factor[e];
    edges.plastic_strain[e] =
        updatedPlasticStrain(edges.plastic_strain[e], load, edges.breaking_strain[e], curve);
    const double elastic = load / curve.youngsModulus();
    const double strain = edges.plastic_strain[e] + elastic;
    const double previous_strain = edges.strain[e];
    edges.strain_rate[e] = (strain - previous_strain) / time_step;
    edges.strain[e] = strain;
    edges.rest_length[e] = edges.original_rest_length[e] * (1.0 + edges.plastic_strain[e]);
    edges.strain_limit[e] = elastic / (1.0 + edges.plastic_strain[e]);
    updateRateFactor(material, time_step, previous_strain, stress > 0.0, e, edges);
  }
}

}  // namespace yarn_tearing
