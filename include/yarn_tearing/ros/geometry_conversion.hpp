#pragma once

#include <geometry_msgs/Point.h>
#include <geometry_msgs/Vector3.h>

#include <Eigen/Core>

namespace yarn_tearing {
namespace ros_layer {

/// Eigen position [m] -> geometry_msgs::Point [m].
inline geometry_msgs::Point toPoint(const Eigen::Vector3d& p) {
  geometry_msgs::Point point;
  point.x = p.x();
  point.y = p.y();
  point.z = p.z();
  return point;
}

/// Eigen vector -> geometry_msgs::Vector3, same unit.
inline geometry_msgs::Vector3 toVector3(const Eigen::Vector3d& v) {
  geometry_msgs::Vector3 vector;
  vector.x = v.x();
  vector.y = v.y();
  vector.z = v.z();
  return vector;
}

/// geometry_msgs::Vector3 -> Eigen vector, same unit.
inline Eigen::Vector3d toEigen(const geometry_msgs::Vector3& v) {
  return Eigen::Vector3d(v.x, v.y, v.z);
}

}  // namespace ros_layer
}  // namespace yarn_tearing
