#pragma once

#include <Eigen/Core>
#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/model/yarn.hpp"

namespace yarn_tearing {

/// Stage 5 (paper §3.3–3.4): from each intact edge's tension [N] to stress, strain, plastic
/// strain, rest length and strain limit.
///
/// - stress sigma = T / area; a negative tension is compression: reported, but it neither yields
///   nor breaks the edge and its elastic strain counts as 0.
/// - the curve at the edge's loading rate is the material's curve with its stresses times the
///   edge's rate factor f (RateDependence; 1 for a rate-independent material), so the edge reads
///   the material's curve at sigma / f.
/// - plastic strain: eps_p = max(eps_p, eps_p*(sigma / f)), eps_p* the plastic strain the curve
///   leaves at a stress, no further than the edge's breaking point.
/// - strain = eps_p + sigma+ / (f E) relative to L0; rest length L0 (1 + eps_p);
///   the next projection holds the edge to the elastic strain of its stress (its strain limit).
/// - the loading rate: strain gained since the edge last became taut over the time since; f for
///   the next step follows from it (1 while the edge is slack).
void updateMaterialResponse(const std::vector<Yarn>& yarns, double time_step, EdgeSet& edges);

}  // namespace yarn_tearing
