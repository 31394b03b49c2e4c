#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/edge_gram_solver.hpp"
#include "yarn_tearing/core/edge_set.hpp"
#include "yarn_tearing/core/vertex_set.hpp"

namespace yarn_tearing {

/// What the tension estimate needs from the step that produced it.
struct TensionEstimateInput {
  const VertexSet* vertices = nullptr;                       ///< after projection (x'', v'')
  const std::vector<Eigen::Vector3d>* start_velocity = nullptr;  ///< v at step start [m/s]
  const std::vector<Eigen::Vector3d>* force = nullptr;       ///< non-constraint forces [N]
  double time_step = 0.0;                                    ///< dt [s]
  double regularization = 0.0;                               ///< lambda [-]
};

/// Stage 4 (paper §3.2): the tensions T_e [N] that stiff springs would have needed to carry the
/// yarn from (x, v) to the length-constrained v'' in one step:
///   min_T  sum_free v |v_v + dt/m_v (F_v + sum_e T_e u_ev) - v''_v|^2 + lambda sum_e D_e (T_e - T'_e)^2
/// u_ev the unit vector from v along edge e, D_e the diagonal of the normal matrix (so lambda is
/// dimensionless: the same in any units and at any mass), T'_e the previous step's estimate (so a
/// steady load is recovered without bias however long the yarn). Pinned and kinematic vertices'
/// rows are left out. The normal equations are solved by EdgeGramSolver: O(N) for chains.
class TensionEstimator {
 public:
  /// Overwrites `tension` (in: previous estimate, out: new one); returns |A T - b| / |b| [-].
  double estimate(const TensionEstimateInput& input, const EdgeSet& edges, EdgeGramSolver& gram,
                  std::vector<double>& tension);

 private:
  std::vector<double> weight_;                 ///< (dt/m_v)^2 for free vertices, else 0 [s^2/kg^2]
  std::vector<Eigen::Vector3d> target_;        ///< b_v: velocity change the tensions explain [m/s]
  std::vector<Eigen::Vector3d> direction_;     ///< unit edge directions
  std::vector<std::uint8_t> active_;           ///< intact edges
  std::vector<double> anchor_;                 ///< previous estimate [N]
};

}  // namespace yarn_tearing
