#pragma once

#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/yarn_spec.hpp"

namespace yarn_tearing {

/// How a single-end tensile test pulls a specimen: constant rate of extension (CRE), as ISO 2062
/// prescribes for yarns (100 % of the gauge length per minute).
struct TensilePullSettings {
  double extension_rate = 1.0 / 60.0;  ///< clamp speed over specimen length [1/s]; 100 %/min
  double time_step = 1.0e-3;           ///< simulation step [s]
  /// Simulated time between recorded trace points [s]; 0 = about 200 points up to the curve's
  /// breaking strain.
  double record_interval = 0.0;
  /// Clamp strain [-] at which an untorn specimen is given up; 0 = 4 x the curve's breaking strain.
  double max_strain = 0.0;
};

/// One recorded point of a pull.
struct TensileSample {
  double elongation = 0.0;  ///< clamp displacement over specimen length [-]
  double force = 0.0;       ///< force on the fixed clamp (the load cell) along the pull [N]
};

/// Outcome of pulling one specimen.
struct TensilePullResult {
  bool torn = false;                 ///< false: reached max_strain without tearing
  double breaking_force = 0.0;       ///< tension of the torn edge at the tear [N]
  double elongation_at_break = 0.0;  ///< clamp displacement at the tear over length [-]
  std::uint32_t torn_edge = 0;       ///< edge that tore (index within the yarn)
  std::vector<TensileSample> trace;  ///< force-elongation record up to the tear (last = the tear)
};

/// Pulls one specimen `spec` (its length is the clamped length) in a virtual CRE tester: vertex 0
/// is the fixed clamp on the load cell, the last vertex the moving clamp, drawn away along the
/// yarn's direction at extension_rate * length. No gravity (the weight of a 0.5 m yarn is about
/// 1e-5 of its strength), no pins other than the clamps and no end mass. Throws
/// std::invalid_argument on an invalid spec or settings.
TensilePullResult pullSpecimen(YarnSpec spec, const TensilePullSettings& settings);

}  // namespace yarn_tearing
