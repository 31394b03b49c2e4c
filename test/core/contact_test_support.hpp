#pragma once

#include <cmath>
#include <vector>

#include "test_support.hpp"

namespace yarn_tearing::test {

/// An obstacle of `shape` at `position` with friction `mu`.
inline Obstacle obstacleAt(ObstacleShape shape, const Eigen::Vector3d& position, double mu) {
  Obstacle o;
  o.name = "obstacle";
  o.shape = shape;
  o.pose = Eigen::Isometry3d::Identity();
  o.pose.translation() = position;
  o.friction = mu;
  return o;
}

/// Total mass of the scene [kg].
inline double totalMass(const Simulator& sim) {
  double mass = 0.0;
  for (double m : sim.scene().vertices.mass) mass += m;
  return mass;
}

/// Deepest point of any yarn segment inside obstacle `o` [m] (0 when none is inside): the
/// distance of each segment's closest point less the yarn radius.
inline double deepestPenetration(const Simulator& sim, const Obstacle& o) {
  const Scene& s = sim.scene();
  double deepest = 0.0;
  Eigen::Vector3d normal;
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    if (!s.edges.intact(e)) continue;
    const Eigen::Vector3d& a = s.vertices.position[s.edges.vertex_a[e]];
    const Eigen::Vector3d& b = s.vertices.position[s.edges.vertex_b[e]];
    const double t = o.closestOnSegment(a, b);
    const double gap = o.signedDistance(a + t * (b - a), normal) - s.yarns[s.edges.yarn[e]].radius;
    deepest = std::max(deepest, -gap);
  }
  return deepest;
}

/// A capsule post along y through the origin.
inline Obstacle postAlongY(double radius, double mu) {
  Obstacle o = obstacleAt(ObstacleShape::kCapsule, Eigen::Vector3d::Zero(), mu);
  o.radius = radius;
  o.half_length = 0.05;
  o.pose.linear() = Eigen::AngleAxisd(-kPi / 2.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
  return o;
}

}  // namespace yarn_tearing::test
