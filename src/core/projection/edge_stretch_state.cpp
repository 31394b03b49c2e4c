#include "yarn_tearing/core/projection/edge_stretch_state.hpp"

namespace yarn_tearing {

void EdgeStretchState::reset(const EdgeSet& edges, const EdgeStretchLimits& limits,
                             double time_step) {
  const std::size_t q = edges.size();
  const double time_step2 = time_step * time_step;
  compliant_shift_.resize(q);
  for (std::size_t e = 0; e < q; ++e) {
    compliant_shift_[e] = limits.constraintCompliance(e) / time_step2;
  }
  max_stretch_ = limits.max_stretch;
  shift_ = compliant_shift_;
  base_length_ = edges.rest_length;
  saturated_.assign(q, 0);
}

bool EdgeStretchState::wouldSwitch(std::size_t e, double m) const {
  const double stretch = compliant_shift_[e] * m;
  return saturated_[e] ? stretch < max_stretch_[e] * (1.0 - kMargin)
                       : stretch > max_stretch_[e] * (1.0 + kMargin);
}

double EdgeStretchState::settle(const EdgeSet& edges, std::size_t e, double m) {
  if (!(m > 0.0)) return release(edges, e);
  return wouldSwitch(e, m) ? set(edges, e, !saturated_[e]) : 0.0;
}

double EdgeStretchState::multiplierAtLength(const EdgeSet& edges, std::size_t e,
                                            double length) const {
  const double stretch = length - edges.rest_length[e];
  if (!(stretch > 0.0)) return 0.0;
  if (stretch <= max_stretch_[e]) return stretch / compliant_shift_[e];
  return (max_stretch_[e] + (stretch - max_stretch_[e]) / kStopCompliance) / compliant_shift_[e];
}

double EdgeStretchState::set(const EdgeSet& edges, std::size_t e, bool saturated) {
  // Held: limit = L + s_max + r s (m - s_max / s), r = kStopCompliance, continuous with the
  // compliant L + s m at the switch. r > 0 keeps the Newton step's system quasi-definite.
  const double old_base = base_length_[e];
  base_length_[e] =
      edges.rest_length[e] + (saturated ? max_stretch_[e] * (1.0 - kStopCompliance) : 0.0);
  shift_[e] = compliant_shift_[e] * (saturated ? kStopCompliance : 1.0);
  saturated_[e] = saturated ? 1 : 0;
  return old_base - base_length_[e];
}

}  // namespace yarn_tearing
