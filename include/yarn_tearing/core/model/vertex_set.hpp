#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace yarn_tearing {

/// How a vertex moves.
enum class VertexMotion : std::uint8_t {
  kFree,       ///< integrated from forces and constraints
  kPinned,     ///< fixed in space
  kKinematic,  ///< follows a target position set from outside (a gripper)
};

/// All vertices of a scene, structure-of-arrays; index = global vertex id.
struct VertexSet {
  std::vector<Eigen::Vector3d> position;          ///< [m]
  std::vector<Eigen::Vector3d> velocity;          ///< [m/s]
  std::vector<double> mass;                       ///< [kg]
  std::vector<double> damping_length;             ///< share of yarn length for air damping [m]
  std::vector<VertexMotion> motion;               ///< free, pinned or kinematic
  std::vector<Eigen::Vector3d> applied_force;     ///< external force set from outside [N]
  std::vector<Eigen::Vector3d> kinematic_target;  ///< target of kinematic vertices [m]
  /// Index of the owning yarn (a fabric's vertices: its warp group, Fabric::warp_group).
  std::vector<std::uint32_t> yarn;

  std::size_t size() const { return position.size(); }
  bool isSupport(std::size_t v) const { return motion[v] != VertexMotion::kFree; }
  /// 1/m for free vertices, 0 for pinned and kinematic ones [1/kg].
  double inverseMass(std::size_t v) const { return isSupport(v) ? 0.0 : 1.0 / mass[v]; }
  /// Appends a free vertex at rest.
  void add(const Eigen::Vector3d& x, double m, double damping_share, std::uint32_t yarn_index);
};

}  // namespace yarn_tearing
