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
  /// Box: radius of its edges and corners [m] (a real table's edge is rounded), in
  /// [0, smallest half extent]; its faces stay where half_extents puts them. The contact rounds
  /// them further where the yarn's mesh needs it (edge_rounding.hpp).
  double edge_radius = 0.0;

  /// Throws std::invalid_argument naming the field and what is allowed.
  void validate() const;
  /// True when `other` is the same solid at the same pose (shape, pose and sizes equal; name
  /// and friction may differ).
  bool sameGeometry(const Obstacle& other) const;
  /// Signed distance [m] from world point `p` to the surface (negative inside) and the outward
  /// unit normal there (the gradient of the distance). `rounding` [m] rounds a box's edges and
  /// corners to that radius, its faces unchanged (the distance to the box shrunk by `rounding`,
  /// less `rounding`; at most the smallest half extent); the other shapes ignore it.
  double signedDistance(const Eigen::Vector3d& p, Eigen::Vector3d& normal,
                        double rounding = 0.0) const {
    if (shape != ObstacleShape::kPlane) return solidDistance(p, normal, rounding);
    // The frame's z axis, without the whole change of frame (a table: a thousand points a step).
    normal = pose.linear().col(2);
    return normal.dot(p - pose.translation());
  }
  /// Signed distance [m] from world point `p` to the surface, without the normal (`rounding`
  /// [m] as above).
  double signedDistance(const Eigen::Vector3d& p, double rounding = 0.0) const;
  /// The Hessian of the signed distance at world point `p` outside the solid [1/m]: the
  /// surface's curvature there (0 on a plane or a box face; `rounding` [m] as above).
  Eigen::Matrix3d curvature(const Eigen::Vector3d& p, double rounding = 0.0) const;
  /// The parameter t in [0, 1] of the point (1 - t) a + t b of segment ab closest to the
  /// obstacle (smallest signed distance; the distance to a convex solid is convex along a line;
  /// `rounding` [m] as above).
  double closestOnSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          double rounding = 0.0) const;
  /// Radius of a ball about the pose's origin that holds the whole solid [m] (infinite for a
  /// plane), for quick rejection.
  double boundingRadius() const;

 private:
  /// signedDistance() of any shape, through the obstacle's frame [m].
  double solidDistance(const Eigen::Vector3d& p, Eigen::Vector3d& normal, double rounding) const;
};

}  // namespace yarn_tearing
