#pragma once

#include <vector>

#include "yarn_tearing/core/scene.hpp"

namespace yarn_tearing {

/// How far each edge may stretch past its (plastic) rest length L in the length-constraint
/// projection: by c T, its elastic stretch under the force T [N] the constraint exerts, but never
/// past its breaking length. Past that the constraint is hard, so a yarn pulled far beyond its
/// strength holds at its breaking length until the tearing stage cuts it, instead of stretching
/// elastically without bound and recoiling from there.
struct EdgeStretchLimits {
  /// Elastic compliance c = L0 / (E A) [m/N]: engineering strain on the original length L0, as
  /// the stress-strain curve is given, so the stretch is L0 sigma / E.
  std::vector<double> compliance;
  /// Largest stretch past L [m]: L0 (1 + eps_b f) - L >= 0, the breaking length (breaking strain
  /// eps_b times the edge's strength factor f) minus the rest length.
  std::vector<double> max_stretch;
};

/// Fills `limits` from the edges' rest lengths, areas and materials.
void computeStretchLimits(const Scene& scene, EdgeStretchLimits& limits);

}  // namespace yarn_tearing
