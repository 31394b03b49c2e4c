#include "yarn_tearing/ros/obstacle_markers.hpp"

#include <algorithm>
#include <cmath>

#include "yarn_tearing/ros/geometry_conversion.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

/// Marker ids within an obstacle's namespace.
enum MarkerId : int { kSolidId = 0, kFirstEndId = 1, kSecondEndId = 2, kForceId = 3 };
constexpr double kArrowShaft = 0.002;  ///< [m] arrow shaft diameter

visualization_msgs::Marker baseMarker(const Obstacle& obstacle, int id, int type,
                                      const std::string& frame_id, const ros::Time& stamp) {
  visualization_msgs::Marker marker;
  marker.header.frame_id = frame_id;
  marker.header.stamp = stamp;
  marker.ns = "obstacles/" + obstacle.name;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.color.r = marker.color.g = marker.color.b = 0.55F;
  marker.color.a = 0.5F;
  return marker;
}

/// Sets `marker`'s pose to `pose` [m] and its scale to `size` [m].
void place(visualization_msgs::Marker& marker, const Eigen::Isometry3d& pose,
           const Eigen::Vector3d& size) {
  const Eigen::Quaterniond q(pose.linear());
  marker.pose.position = toPoint(pose.translation());
  marker.pose.orientation.w = q.w();
  marker.pose.orientation.x = q.x();
  marker.pose.orientation.y = q.y();
  marker.pose.orientation.z = q.z();
  marker.scale = toVector3(size);
}

visualization_msgs::Marker solid(const Obstacle& o, const std::string& frame_id,
                                 const ros::Time& stamp) {
  using visualization_msgs::Marker;
  switch (o.shape) {
    case ObstacleShape::kPlane: {
      Marker marker = baseMarker(o, kSolidId, Marker::CUBE, frame_id, stamp);
      const Eigen::Isometry3d slab =
          o.pose * Eigen::Translation3d(0.0, 0.0, -0.5 * kPlaneMarkerThickness);
      place(marker, slab,
            Eigen::Vector3d(kPlaneMarkerSize, kPlaneMarkerSize, kPlaneMarkerThickness));
      return marker;
    }
    case ObstacleShape::kBox: {
      Marker marker = baseMarker(o, kSolidId, Marker::CUBE, frame_id, stamp);
      place(marker, o.pose, 2.0 * o.half_extents);
      return marker;
    }
    case ObstacleShape::kSphere: {
      Marker marker = baseMarker(o, kSolidId, Marker::SPHERE, frame_id, stamp);
      place(marker, o.pose, Eigen::Vector3d::Constant(2.0 * o.radius));
      return marker;
    }
    case ObstacleShape::kCapsule:
      break;
  }
  Marker marker = baseMarker(o, kSolidId, Marker::CYLINDER, frame_id, stamp);
  place(marker, o.pose, Eigen::Vector3d(2.0 * o.radius, 2.0 * o.radius, 2.0 * o.half_length));
  return marker;
}

/// The sphere closing the capsule's end at z = `side` * half_length.
visualization_msgs::Marker capsuleEnd(const Obstacle& o, int id, double side,
                                      const std::string& frame_id, const ros::Time& stamp) {
  visualization_msgs::Marker marker =
      baseMarker(o, id, visualization_msgs::Marker::SPHERE, frame_id, stamp);
  place(marker, o.pose * Eigen::Translation3d(0.0, 0.0, side * o.half_length),
        Eigen::Vector3d::Constant(2.0 * o.radius));
  return marker;
}

visualization_msgs::Marker forceArrow(const Obstacle& o, const ContactWrench& wrench,
                                      const std::string& frame_id, const ros::Time& stamp) {
  visualization_msgs::Marker marker =
      baseMarker(o, kForceId, visualization_msgs::Marker::ARROW, frame_id, stamp);
  const double force = wrench.force.norm();
  if (!(force > 0.0) || !std::isfinite(force) || !wrench.torque.allFinite()) {
    marker.action = visualization_msgs::Marker::DELETE;
    return marker;
  }
  // The point of the line of action closest to the origin o: o + F x tau_o / |F|^2.
  const Eigen::Vector3d tip =
      o.pose.translation() + wrench.force.cross(wrench.torque) / (force * force);
  const double length =
      std::clamp(kArrowShortest + kArrowLengthPerDecade * std::log10(force / kArrowSmallestForce),
                 kArrowShortest, kArrowLongest);
  marker.pose.orientation.w = 1.0;
  marker.points.push_back(toPoint(tip - (length / force) * wrench.force));
  marker.points.push_back(toPoint(tip));
  marker.scale.x = kArrowShaft;
  marker.scale.y = 2.0 * kArrowShaft;
  marker.scale.z = 3.0 * kArrowShaft;
  marker.color.r = marker.color.b = 1.0F;
  marker.color.g = 0.0F;
  marker.color.a = 1.0F;
  return marker;
}

}  // namespace

std::vector<visualization_msgs::Marker> obstacleMarkers(const Obstacle& obstacle,
                                                        const ContactWrench& wrench,
                                                        const std::string& frame_id,
                                                        const ros::Time& stamp) {
  std::vector<visualization_msgs::Marker> markers = {solid(obstacle, frame_id, stamp)};
  if (obstacle.shape == ObstacleShape::kCapsule) {
    markers.push_back(capsuleEnd(obstacle, kFirstEndId, -1.0, frame_id, stamp));
    markers.push_back(capsuleEnd(obstacle, kSecondEndId, 1.0, frame_id, stamp));
  }
  markers.push_back(forceArrow(obstacle, wrench, frame_id, stamp));
  return markers;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
