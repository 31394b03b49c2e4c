#pragma once

#include <Eigen/Geometry>
#include <string>

namespace yarn_tearing {

/// Shape of an obstacle, in the obstacle's own frame (its pose maps it into the world).
enum class ObstacleShape {
  kPlane,    ///< the half-space z <= 0 of its frame: the surface is the frame's xy plane
  kBox,      ///< |x| <= half_extents.x, |y| <= half_extents.y, |z| <= half_extents.z
  kSphere,   ///< |p| <= radius
  kCapsule,  ///< within radius of the segment z in [-half_length, half_length] on the z axis
             ///< (a cylinder with rounded ends: a peg, a post, a gripper finger)
};

/// A rigid obstacle the yarns touch but do not move: a table, a peg, a post, a finger. Its pose
/// may be changed before every step (Simulator::setObstaclePose): a moving obstacle carries the
/// yarn points that stick to it.
struct Obstacle {
  std::string name;                                        ///< for reports (unique in a simulator)
  ObstacleShape shape = ObstacleShape::kPlane;             ///< which solid
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< obstacle frame in the world [m]
  Eigen::Vector3d half_extents = Eigen::Vector3d::Constant(0.05);  ///< box half sizes [m]
  double radius = 0.01;                                            ///< sphere or capsule radius [m]
  double half_length = 0.05;  ///< capsule: half the length of its axis segment [m]
  double friction = 0.0;      ///< Coulomb friction coefficient mu [-] (static = kinetic)

  /// Throws std::invalid_argument naming the field and what is allowed.
  void validate() const;
  /// Signed distance [m] from world point `p` to the surface (negative inside) and the outward
  /// unit normal there (the gradient of the distance).
  double signedDistance(const Eigen::Vector3d& p, Eigen::Vector3d& normal) const {
    if (shape != ObstacleShape::kPlane) return solidDistance(p, normal);
    // The frame's z axis, without the whole change of frame (a table: a thousand points a step).
    normal = pose.linear().col(2);
    return normal.dot(p - pose.translation());
  }
  /// Signed distance [m] from world point `p` to the surface, without the normal.
  double signedDistance(const Eigen::Vector3d& p) const;
  /// The Hessian of the signed distance at world point `p` outside the solid [1/m]: the
  /// surface's curvature there (0 on a plane or a box face).
  Eigen::Matrix3d curvature(const Eigen::Vector3d& p) const;
  /// The parameter t in [0, 1] of the point (1 - t) a + t b of segment ab closest to the
  /// obstacle (smallest signed distance; the distance to a convex solid is convex along a line).
  double closestOnSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  /// Radius of a ball about the pose's origin that holds the whole solid [m] (infinite for a
  /// plane), for quick rejection.
  double boundingRadius() const;

 private:
  /// signedDistance() of any shape, through the obstacle's frame [m].
  double solidDistance(const Eigen::Vector3d& p, Eigen::Vector3d& normal) const;
};

}  // namespace yarn_tearing
