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
  double tension = 0.0;         ///< axial force the edge carried when it tore [N]
  double stress = 0.0;          ///< tension over the cross-section [Pa]
  double strain = 0.0;          ///< engineering strain on the original length L0 [-]
  double plastic_strain = 0.0;  ///< permanent strain on L0 [-]
  /// Rate of the edge's geometric strain |x_b - x_a| / L0 - 1 in the step that tore it [1/s]:
  /// the ends' relative velocity along the edge over L0 (a uniform pull at speed v over a gauge
  /// length L reads v / L; negative while the edge shortens).
  double strain_rate = 0.0;
};

}  // namespace yarn_tearing
