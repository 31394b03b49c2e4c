#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {

/// A held vertex is moved towards its kinematic target by at most its yarn's snap-back speed
/// c * eps_b per step (Material::snapBackSpeed: 160 m/s for cotton). No load can move a yarn
/// faster, so a faster grasp only tears the yarn at the grasp, as it does at that speed; and a
/// target jumping metres per step (a tf frame teleported) would throw the vertices it drags at
/// that speed and start the projection far from its solution (doc/node.md, "Bad input").
struct RequestedTarget {
  std::uint32_t vertex = 0;  ///< global vertex id [-]
  Eigen::Vector3d target;    ///< where the vertex was asked to go [m]
};

/// Puts each kinematic target of `scene` farther than snapBackSpeed * `time_step` [s] from its
/// vertex at that distance on the way to it; returns the requested targets it moved.
std::vector<RequestedTarget> limitHeldTargets(Scene& scene, double time_step);

/// Gives the vertices of `requested` still held their requested targets back (so that a limited
/// vertex goes on towards its target in the next steps).
void restoreHeldTargets(const std::vector<RequestedTarget>& requested, Scene& scene);

}  // namespace yarn_tearing
