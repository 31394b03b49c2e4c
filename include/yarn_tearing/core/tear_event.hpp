#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace yarn_tearing {

/// One edge that tore, with the state it tore in (published as the yarn_tearing/BreakEvent
/// message).
struct TearEvent {
  std::uint32_t yarn = 0;                              ///< yarn index in the scene
  std::uint32_t edge = 0;                              ///< edge index within the yarn
  std::uint32_t vertex_a = 0;                          ///< first vertex within the yarn
  std::uint32_t vertex_b = 0;                          ///< second vertex within the yarn
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< edge midpoint [m]
  double time = 0.0;            ///< simulated time at the end of the step [s]
  double tension = 0.0;         ///< [N]
  double stress = 0.0;          ///< [Pa]
  double strain = 0.0;          ///< [-]
  double plastic_strain = 0.0;  ///< [-]
  double strain_rate = 0.0;     ///< [1/s]
};

}  // namespace yarn_tearing
