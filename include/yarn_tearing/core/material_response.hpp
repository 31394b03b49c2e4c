#pragma once

#include <Eigen/Core>
#include <vector>

#include "yarn_tearing/core/edge_set.hpp"
#include "yarn_tearing/core/yarn.hpp"

namespace yarn_tearing {

/// Stage 5 (paper §3.3–3.4): from each intact edge's tension [N] to stress, strain, plastic
/// strain, rest length and strain limit.
///
/// - stress sigma = T / area; a negative tension is compression: reported, but it neither yields
///   nor breaks the edge and its elastic strain counts as 0.
/// - plastic strain: eta = 0: eps_p = max(eps_p, eps_p*(sigma)), eps_p*(sigma) the plastic strain
///   the curve leaves at sigma; eta > 0: d(eps_p)/dt = E (eps_p* - eps_p)+ / eta, integrated
///   exactly over the step, so slow loading flows further than fast loading (§3.4).
/// - strain = eps_p + sigma+ / E relative to L0; rest length L0 (1 + eps_p);
///   the next projection holds the edge to the elastic strain of its stress (its strain limit).
void updateMaterialResponse(const std::vector<Yarn>& yarns, double time_step, EdgeSet& edges);

}  // namespace yarn_tearing
