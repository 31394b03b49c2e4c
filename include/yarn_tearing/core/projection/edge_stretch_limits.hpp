#pragma once

#include <vector>

#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"

namespace yarn_tearing {

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
double stabilitySpringConstant(const VertexSet& vertices, std::uint32_t a, std::uint32_t b,
                               const SimulationParameters& p);

/// Fills `limits` from the edges' rest lengths, areas and materials, the vertex masses and the
/// time step.
void computeStretchLimits(const Scene& scene, const SimulationParameters& parameters,
                          EdgeStretchLimits& limits);

}  // namespace yarn_tearing
