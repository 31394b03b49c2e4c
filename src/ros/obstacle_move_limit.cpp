#include "yarn_tearing/ros/obstacle_move_limit.hpp"

#include <algorithm>
#include <limits>

namespace yarn_tearing {
namespace ros_layer {

double obstacleStepLimit(const Scene& scene) {
  const std::vector<double>& lengths = scene.edges.original_rest_length;
  if (lengths.empty()) {
    return std::numeric_limits<double>::infinity();
  }
  return kObstacleStepFraction * *std::min_element(lengths.begin(), lengths.end());
}

Eigen::Isometry3d limitedObstacleMove(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to,
                                      double max_translation) {
  const Eigen::Vector3d travel = to.translation() - from.translation();
  const double distance = travel.norm();
  if (!(distance > max_translation)) {
    return to;
  }
  const double share = max_translation / distance;
  const Eigen::Quaterniond start(from.rotation());
  const Eigen::Quaterniond end(to.rotation());
  Eigen::Isometry3d moved = Eigen::Isometry3d::Identity();
  moved.linear() = start.slerp(share, end).toRotationMatrix();
  moved.translation() = from.translation() + share * travel;
  return moved;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
