#pragma once

#include <Eigen/Geometry>

#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Fraction of the scene's shortest segment rest length an attached obstacle may travel in one
/// step [-]. A yarn point then starts each step at most this far inside a solid that came to it,
/// which the contact pushes out in that step; a frame jumping into a fabric's plane (a finger's
/// frame teleported into the cloth) would otherwise meet segments pushed sideways in the plane,
/// which the length constraints hold back: a single step of a 16 x 12 patch ran for minutes.
constexpr double kObstacleStepFraction = 0.1;

/// Longest translation [m] of an attached obstacle in one step in `scene`:
/// kObstacleStepFraction of its shortest segment rest length (infinite without segments).
double obstacleStepLimit(const Scene& scene);

/// The pose at most `max_translation` [m] from `from` towards `to`: `to` itself when it is that
/// close, else the translation moved that far and the rotation turned by the same share (slerp).
Eigen::Isometry3d limitedObstacleMove(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to,
                                      double max_translation);

}  // namespace ros_layer
}  // namespace yarn_tearing
