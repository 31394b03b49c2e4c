#include "yarn_tearing/core/projection/edge_stretch_limits.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace yarn_tearing {

namespace {

/// The stresses [Pa] on the reference curve between which edge e's plastic elongation is linear
/// in the stress, from `low` (the soft spring's alone) to `cap` (its breaking point): the curve's
/// points and the crossings of the current plastic strain `plastic`; with the curve's plastic
/// strain at each [-].
void flowBreakpoints(const StressStrainCurve& curve, double low, double cap, double plastic,
                     FlowBreakpoints& breakpoints) {
  std::vector<double>& stresses = breakpoints.stress;
  std::vector<double>& at = breakpoints.plastic_strain;
  stresses.clear();
  stresses.push_back(low);
  for (const CurvePoint& p : curve.points()) {
    if (p.stress > low && p.stress < cap) stresses.push_back(p.stress);
  }
  if (cap > low) stresses.push_back(cap);
  at.resize(stresses.size());
  for (std::size_t i = 0; i < stresses.size(); ++i) {
    at[i] = curve.plasticStrainAtStress(stresses[i]);
  }
  // Where the curve's plastic strain crosses the edge's own, max(eps_p,n, eps_p) kinks.
  for (std::size_t i = 0; i + 1 < stresses.size(); ++i) {
    const double e0 = at[i] - plastic;
    const double e1 = at[i + 1] - plastic;
    if ((e0 < 0.0) == (e1 < 0.0) || e0 == e1) continue;
    const double t = -e0 / (e1 - e0);
    if (t <= 0.0 || t >= 1.0) continue;
    const double crossing = stresses[i] + t * (stresses[i + 1] - stresses[i]);
    const auto next = static_cast<std::ptrdiff_t>(i) + 1;
    stresses.insert(stresses.begin() + next, crossing);
    at.insert(at.begin() + next, curve.plasticStrainAtStress(crossing));
    ++i;
  }
}

/// The stress [Pa] on the reference curve at which its plastic strain is `plastic` [-]: the
/// yield stress of an edge hardened that far (the curve's yield stress for a virgin one).
double currentYieldStress(const StressStrainCurve& curve, double plastic) {
  if (!(plastic > 0.0)) return curve.yieldStress();
  const std::vector<CurvePoint>& points = curve.points();
  const double modulus = curve.youngsModulus();
  std::size_t upper = 2;
  while (upper + 1 < points.size() &&
         points[upper].strain - points[upper].stress / modulus < plastic) {
    ++upper;
  }
  const CurvePoint& p0 = points[upper - 1];
  const CurvePoint& p1 = points[upper];
  const double e0 = p0.strain - p0.stress / modulus;
  const double e1 = p1.strain - p1.stress / modulus;
  return p0.stress + (plastic - e0) / (e1 - e0) * (p1.stress - p0.stress);
}

}  // namespace

void computeFlowLimits(const Scene& scene, EdgeStretchLimits& limits) {
  const EdgeSet& edges = scene.edges;
  limits.yarns = &scene.yarns;
  limits.flow_start.assign(edges.size(), std::numeric_limits<double>::infinity());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e)) continue;
    const StressStrainCurve& curve = scene.yarns[edges.yarn[e]].material.curve;
    const double plastic = edges.plastic_strain[e];
    // Flow stops at the edge's breaking point (updateMaterialResponse): none where the edge's
    // yield point is past it (plastic strain rises with stress along the curve).
    const bool virgin = !(plastic > 0.0);
    const bool can_flow =
        virgin
            ? curve.yieldStrain() < edges.breaking_strain[e]
            : plastic < curve.plasticStrainAtStress(curve.stressAtStrain(edges.breaking_strain[e]));
    if (!can_flow) continue;
    const double yield = virgin ? curve.yieldStress() : currentYieldStress(curve, plastic);
    limits.flow_start[e] = edges.rate_factor[e] * edges.area[e] * yield - edges.spring_tension[e];
  }
}

void flowKnots(const EdgeSet& edges, const std::vector<Yarn>& yarns, std::size_t e,
               std::vector<FlowKnot>& knots, FlowBreakpoints& breakpoints) {
  knots.clear();
  const StressStrainCurve& curve = yarns[edges.yarn[e]].material.curve;
  const double scale = edges.rate_factor[e] * edges.area[e];  // T = f A sigma_ref [m^2]
  const double spring = edges.spring_tension[e];
  const double plastic = edges.plastic_strain[e];
  const double original = edges.original_rest_length[e];
  const double cap = curve.stressAtStrain(edges.breaking_strain[e]);
  flowBreakpoints(curve, spring / scale, cap, plastic, breakpoints);
  const std::vector<double>& stresses = breakpoints.stress;
  // The plastic elongation at breakpoint i [m] (the cap's plastic strain where it is capped).
  const auto elongation = [&](std::size_t i) {
    const double at =
        stresses[i] <= cap ? breakpoints.plastic_strain[i] : curve.plasticStrainAtStress(cap);
    return original * std::max(at - plastic, 0.0);
  };
  for (std::size_t i = 0; i < stresses.size(); ++i) {
    FlowKnot knot;
    knot.force = std::max(scale * stresses[i] - spring, 0.0);
    knot.elongation = elongation(i);
    if (i + 1 < stresses.size()) {
      const double span = scale * (stresses[i + 1] - stresses[i]);
      knot.slope = span > 0.0 ? (elongation(i + 1) - knot.elongation) / span : 0.0;
    }
    // A kink that changes nothing (no flow before and after) is left out.
    const bool flat_start = knots.empty() && knot.elongation == 0.0 && knot.slope == 0.0;
    const bool same = !knots.empty() && knots.back().slope == knot.slope;
    if (!flat_start && !same) knots.push_back(knot);
  }
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
