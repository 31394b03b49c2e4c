#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/model/vertex_set.hpp"
#include "yarn_tearing/core/projection/edge_gram_solver.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"

namespace yarn_tearing {

/// What the tension estimate needs from the step that produced it.
struct TensionEstimateInput {
  const VertexSet* vertices = nullptr;                            ///< after projection (x'', v'')
  const std::vector<Eigen::Vector3d>* start_velocity = nullptr;   ///< v at step start [m/s]
  const std::vector<Eigen::Vector3d>* force = nullptr;            ///< non-constraint forces [N]
  double time_step = 0.0;                                         ///< dt [s]
  double regularization = 0.0;                                    ///< lambda [-]
  TensionRowWeighting rows = TensionRowWeighting::kForceBalance;  ///< row weighting
  TensionSource source = TensionSource::kConstraintForce;         ///< solve, or check T'
};

/// Stage 4 (paper §3.2): the tensions T_e [N] that stiff springs would have needed to carry the
/// yarn from (x, v) to the length-constrained v'' in one step:
///   min_T  sum_free v s_v^2 |m_v (v''_v - v_v) / dt - F_v - sum_e T_e u_ev|^2
///          + lambda sum_e D_e (T_e - T'_e)^2
/// with s_v = 1 (force-balance rows, the default) or dt / m_v (the paper's velocity rows),
/// u_ev the unit vector from v along edge e, D_e the diagonal of the normal matrix (so lambda is
/// dimensionless: the same in any units and at any mass) and T'_e the force the projection's own
/// constraint exerted (LengthConstraintProjection::constraintForce). The paper regularizes toward
/// 0; toward T'_e, the tensions the velocities do determine come out the same, and those they do
/// not (a taut span between two supports moves no free vertex) take the constraint's force rather
/// than 0. Pinned and kinematic vertices' rows are left out. The normal equations are solved by
/// EdgeGramSolver: O(N) for chains.
///
/// With TensionSource::kConstraintForce (the default) nothing is solved: T = T', and the
/// residual |A T' - b| / |b| tells how well the constraint forces explain the free vertices'
/// motion (the paper's equation, checked rather than solved).
class TensionEstimator {
 public:
  /// `tension` in: the prior T'_e [N]; out: the estimate (unchanged with kConstraintForce).
  /// Returns the relative residual |A T - b| / |b| [-] of the force balances.
  double estimate(const TensionEstimateInput& input, const EdgeSet& edges, EdgeGramSolver& gram,
                  std::vector<double>& tension);

 private:
  /// Solves the least squares in place (`tension`: T' in, estimate out).
  void solve(const EdgeSet& edges, double regularization, EdgeGramSolver& gram,
             std::vector<double>& tension);

  std::vector<double> weight_;              ///< s_v^2 for free vertices, else 0
  std::vector<Eigen::Vector3d> target_;     ///< b_v: force the tensions must explain [N]
  std::vector<Eigen::Vector3d> direction_;  ///< unit edge directions
  std::vector<std::uint8_t> active_;        ///< intact edges
  std::vector<double> anchor_;              ///< prior T'_e [N]
};

}  // namespace yarn_tearing
