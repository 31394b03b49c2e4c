#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "yarn_tearing/core/model/fabric_segment.hpp"

namespace yarn_tearing {

/// One edge that tore, with the state it tore in (published as the yarn_tearing/BreakEvent
/// message).
/// A fabric's segment tears like a yarn's edge; the event then also names the fabric and the
/// segment (family, yarn within the family, segment along it).
struct TearEvent {
  /// Yarn index in the scene (for a fabric: its warp or weft group, Fabric::warp_group).
  std::uint32_t yarn = 0;
  std::uint32_t edge = 0;      ///< edge index within the yarn (or group)
  std::uint32_t vertex_a = 0;  ///< first vertex within the yarn (fabric: row * ends + column)
  std::uint32_t vertex_b = 0;  ///< second vertex within the yarn (fabric: row * ends + column)
  std::int32_t fabric = -1;    ///< fabric index in the scene, or -1 for a yarn's edge
  FabricSegment segment;       ///< the fabric's family, yarn and segment (when fabric >= 0)
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< edge midpoint [m]
  double time = 0.0;            ///< simulated time at the end of the step [s]
  double tension = 0.0;         ///< [N]
  double stress = 0.0;          ///< [Pa]
  double strain = 0.0;          ///< [-]
  double plastic_strain = 0.0;  ///< [-]
  double strain_rate = 0.0;     ///< [1/s]
};

}  // namespace yarn_tearing
