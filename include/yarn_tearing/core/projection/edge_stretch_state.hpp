#pragma once

#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/projection/edge_stretch_limits.hpp"

namespace yarn_tearing {

/// Whether each edge is compliant or held at its largest stretch during one projection, and the
/// linear limit that follows. A compliant edge may be L + s m long (s = c / dt^2 [1/kg], m its
/// multiplier [kg m]); a held one L + s_max, plus a stop 10^6 times stiffer than the yarn for
/// the force beyond (so that the systems stay quasi-definite). Both regimes are linear in m, so
/// the projection's linear complementarity problem keeps its form: limit = B + S m, with the base
/// length B [m] and the shift S [1/kg] given per edge here.
class EdgeStretchState {
 public:
  /// Takes the compliance terms s = c / dt^2 and the largest stretches; all edges compliant.
  void reset(const EdgeSet& edges, const EdgeStretchLimits& limits, double time_step);

  /// Sets edge e to the regime that multiplier `m` [kg m] puts it in; returns B_old - B_new [m].
  double settle(const EdgeSet& edges, std::size_t e, double m);
  /// Makes edge e compliant (m = 0: a slack edge is never held at its largest stretch).
  double release(const EdgeSet& edges, std::size_t e) { return set(edges, e, false); }
  /// True when multiplier `m` would put edge e in the other regime. A relative margin keeps an
  /// edge right at its largest stretch from switching back and forth on round-off.
  bool wouldSwitch(std::size_t e, double m) const;

  /// S per edge [1/kg]: s, or 10^-6 s when saturated.
  const std::vector<double>& shift() const { return shift_; }
  /// B per edge [m]: L, or L + (1 - 10^-6) s_max when saturated.
  const std::vector<double>& baseLength() const { return base_length_; }
  /// The multiplier [kg m] at which edge e, `length` [m] long, is exactly at its limit: the
  /// force (times dt^2) of a stiff spring of the edge's compliance stretched to that length, and
  /// of the stop past its largest stretch; 0 when the edge is not stretched. For an edge whose
  /// vertices are all pinned or kinematic, which no projection can move: its length is given.
  double multiplierAtLength(const EdgeSet& edges, std::size_t e, double length) const;
  /// The limit B + S m [m] of edge e under multiplier `m` [kg m].
  double limit(std::size_t e, double m) const { return base_length_[e] + shift_[e] * m; }

 private:
  double set(const EdgeSet& edges, std::size_t e, bool saturated);

  static constexpr double kMargin = 1e-9;  ///< relative, see wouldSwitch
  /// Compliance of the stop at the largest stretch, relative to the yarn's [-].
  static constexpr double kStopCompliance = 1e-6;
  std::vector<double> compliant_shift_;  ///< s = c / dt^2 [1/kg]
  std::vector<double> max_stretch_;      ///< s_max [m]
  std::vector<double> shift_;            ///< S [1/kg]
  std::vector<double> base_length_;      ///< B [m]
  std::vector<std::uint8_t> saturated_;  ///< held at the largest stretch
};

}  // namespace yarn_tearing
