#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {

/// Yarns (indices into scene.yarns, ascending) with a non-finite value in any vertex's position
/// or velocity, any edge's rest length, strain limit, tension, stress, strain, plastic strain or
/// strain rate, or any of their vertices' `support_force` [N] (one per vertex). A fabric is
/// listed whole: both its warp and its weft group.
std::vector<std::uint32_t> nonFiniteYarns(const Scene& scene,
                                          const std::vector<Eigen::Vector3d>& support_force);

/// Puts every vertex and edge of yarn `yarn` back as it is in `initial` (same topology): at
/// rest where it started, untorn, unloaded, its applied forces cleared and its grasps released
/// (pins as at the start).
void restoreYarn(const Scene& initial, std::uint32_t yarn, Scene& scene);

}  // namespace yarn_tearing
