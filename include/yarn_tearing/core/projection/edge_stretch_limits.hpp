#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"

namespace yarn_tearing {

/// A kink of an edge's plastic flow within one step. From the constraint force `force` [N] on,
/// the edge's length limit grows by `slope` [m/N] beyond what its elastic compliance gives:
/// L0 (1/H - 1/E) / (f A) on a segment of the curve of slope H past the edge's current yield
/// stress, 0 where it does not flow. `elongation` [m] is the plastic elongation
/// L0 (eps_p - eps_p,n) the step's flow has reached at that force.
struct FlowKnot {
  double force = 0.0;       ///< constraint force where the kink is [N]
  double elongation = 0.0;  ///< plastic elongation there [m]
  double slope = 0.0;       ///< its growth per newton of constraint force from there on [m/N]
};

/// How stiff each edge is and how far it may stretch past its (plastic) rest length L in one step.
/// The edge's elastic stiffness E A / L0 is shared between the explicit soft spring (stage 1) and
/// the compliant length constraint (stage 3), in parallel: the spring takes k_s, the constraint
/// the rest, so that the two together are exactly as stiff as the material at any time step. The
/// constraint lets the edge stretch by c_k T under the force T [N] it exerts, but never past its
/// breaking length: past that it is hard, so a yarn pulled far beyond its strength holds at its
/// breaking length until the tearing stage cuts it.
struct EdgeStretchLimits {
  /// Elastic compliance of the whole edge c = L0 / (f E A) [m/N]: engineering strain on the
  /// original length L0, as the stress-strain curve is given, so the stretch is L0 sigma / (f E),
  /// f the edge's rate factor (EdgeSet::rate_factor).
  std::vector<double> compliance;
  /// Soft-spring constant k_s [N/m]: soft_spring_ratio m_min / dt^2 (m_min the lighter free
  /// vertex), but at most kSoftSpringShare of the edge's stiffness 1 / c.
  std::vector<double> soft_spring;
  /// Largest stretch past L [m]: L0 (1 + eps_b f) - L >= 0, the breaking length (breaking strain
  /// eps_b times the edge's strength factor f) minus the rest length.
  std::vector<double> max_stretch;

  /// Constraint force [N] from which each edge flows plastically in the step: f A sigma_y,n -
  /// T_s, sigma_y,n the stress its current plastic strain was reached at (its current yield
  /// stress), T_s its soft spring's tension; infinite where it cannot flow before its breaking
  /// point. Empty (no flow: elastic up to the breaking length) unless computeFlowLimits ran.
  std::vector<double> flow_start;
  /// The scene's yarns (their curves) while flow_start is set, for flowKnots().
  const std::vector<Yarn>* yarns = nullptr;

  /// Largest share of an edge's elastic stiffness its soft spring may take [-].
  static constexpr double kSoftSpringShare = 0.5;

  /// Compliance of edge e's length constraint c_k = c / (1 - k_s c) [m/N]: in parallel with the
  /// soft spring it gives the edge's own compliance c.
  double constraintCompliance(std::size_t e) const {
    return compliance[e] / (1.0 - soft_spring[e] * compliance[e]);
  }
};

/// The stiffest explicit spring between vertices `a` and `b` that stays stable [N/m]:
/// soft_spring_ratio * (the lighter free vertex's mass) / dt^2; 0 when both are held.
inline double stabilitySpringConstant(const VertexSet& vertices, std::uint32_t a, std::uint32_t b,
                                      const SimulationParameters& p) {
  double lighter = 0.0;
  if (!vertices.isSupport(a)) lighter = vertices.mass[a];
  if (!vertices.isSupport(b)) {
    lighter = lighter > 0.0 ? std::min(lighter, vertices.mass[b]) : vertices.mass[b];
  }
  return p.soft_spring_ratio * lighter / (p.time_step * p.time_step);
}

/// Fills `limits` from the edges' rest lengths, areas and materials, the vertex masses and the
/// time step.
void computeStretchLimits(const Scene& scene, const SimulationParameters& parameters,
                          EdgeStretchLimits& limits);

/// Fills limits.flow_start (and limits.yarns): where each intact edge starts to flow
/// plastically within the step under a constraint force T_c [N] beside its soft spring's tension
/// (EdgeSet::spring_tension, so after stage 1's forces). Cheap for edges far from yield; their
/// kinks are found only for the edges a projection takes past flow_start (flowKnots).
void computeFlowLimits(const Scene& scene, EdgeStretchLimits& limits);

/// Scratch of flowKnots(): the stresses [Pa] between which an edge's plastic elongation is linear
/// in the stress, and the reference curve's plastic strain at each [-].
struct FlowBreakpoints {
  std::vector<double> stress;
  std::vector<double> plastic_strain;
};

/// Edge e's plastic flow within the step as kinks by rising constraint force T_c [N]: the
/// plastic elongation L0 (max(eps_p,n, eps_p((T_s + T_c) / (f A))) - eps_p,n), eps_p the
/// curve's plastic strain at a stress, flow stopping at the edge's breaking point as in the
/// material update (doc/method.md, "Plastic flow within the step"). Replaces `knots`;
/// `breakpoints` is scratch.
void flowKnots(const EdgeSet& edges, const std::vector<Yarn>& yarns, std::size_t e,
               std::vector<FlowKnot>& knots, FlowBreakpoints& breakpoints);

}  // namespace yarn_tearing
