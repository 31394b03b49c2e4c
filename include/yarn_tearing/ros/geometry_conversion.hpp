#pragma once

#include <geometry_msgs/Point.h>
#include <geometry_msgs/Vector3.h>

#include <Eigen/Core>

namespace yarn_tearing {
namespace ros_layer {

/// Eigen vector -> any message with x, y, z fields (Point, Vector3), same unit.
template <typename Message>
Message toXyzMessage(const Eigen::Vector3d& v) {
  Message message;
  message.x = v.x();
  message.y = v.y();
  message.z = v.z();
  return message;
}

/// Eigen position [m] -> geometry_msgs::Point [m].
inline geometry_msgs::Point toPoint(const Eigen::Vector3d& p) {
  return toXyzMessage<geometry_msgs::Point>(p);
}

/// Eigen vector -> geometry_msgs::Vector3, same unit.
inline geometry_msgs::Vector3 toVector3(const Eigen::Vector3d& v) {
  return toXyzMessage<geometry_msgs::Vector3>(v);
}

/// geometry_msgs::Vector3 -> Eigen vector, same unit.
inline Eigen::Vector3d toEigen(const geometry_msgs::Vector3& v) {
  return Eigen::Vector3d(v.x, v.y, v.z);
}

}  // namespace ros_layer
}  // namespace yarn_tearing
