#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/edge_incidence.hpp"
#include "yarn_tearing/core/edge_set.hpp"
#include "yarn_tearing/core/edge_stretch_state.hpp"
#include "yarn_tearing/core/pattern_cached_ldlt.hpp"
#include "yarn_tearing/core/taut_frontier.hpp"

namespace yarn_tearing {

/// One Newton step of the exact implicit projection, with geometric stiffness:
///   M (x - x~) + J(x)^T m = 0,    C_e(x) - s_e m_e = 0 for the taut edges,  m >= 0,
/// C_e = |x_b - x_a| - B_e (B_e the base length: the rest length, or the breaking length where
/// the stretch is at its largest), s_e = c_e / dt^2 the compliance term [1/kg], m the multipliers
/// [kg*m]. Linearized, (M + sum_e m_e Hess C_e) dx + J^T m' = -M (x - x~) and J dx - s m' = -C,
/// a quasi-definite system solved by sparse LDL^T. The geometric stiffness keeps a light vertex
/// between two taut edges from being flung across the line (what stalls the fast projection
/// when a heavy end swings a light yarn), and the fixed point conserves momentum exactly.
/// The taut set is settled by block principal pivoting: edges whose multiplier comes out
/// negative are released, slack edges the step would stretch are taken in (runs of them at once,
/// by a TautFrontier), and it is solved again.
class StiffNewtonStep {
 public:
  /// Moves `position` by one step and overwrites `multiplier` (0 for edges not taut). `taut`
  /// marks the edges taken as equalities (updated when edges are released); `movable` the edges
  /// that may take part; `inverse_mass` is 0 for pinned and kinematic vertices; `stretch_state`
  /// gives B_e and s_e per edge, and is switched where a taut edge's force crosses the one that
  /// reaches its breaking length.
  void apply(const std::vector<Eigen::Vector3d>& predicted, const std::vector<double>& inverse_mass,
             const EdgeSet& edges, const EdgeIncidence& incidence, EdgeStretchState& stretch_state,
             const std::vector<std::uint8_t>& movable, std::vector<std::uint8_t>& taut,
             std::vector<Eigen::Vector3d>& position, std::vector<double>& multiplier);

 private:
  /// Assembles and solves the system for the current `taut` set into solution_.
  bool solve(const std::vector<Eigen::Vector3d>& predicted, const std::vector<double>& inverse_mass,
             const EdgeSet& edges, const EdgeIncidence& incidence,
             const EdgeStretchState& stretch_state, const std::vector<std::uint8_t>& taut,
             const std::vector<Eigen::Vector3d>& position, const std::vector<double>& multiplier);

  /// Length minus base length [m] of a slack edge after the solved step, to first order.
  double linearizedStretch(const EdgeSet& edges, const EdgeStretchState& stretch_state,
                           std::size_t e, const std::vector<Eigen::Vector3d>& position) const;

  static constexpr int kMaxPivotingPasses = 30;    ///< re-solves after changing the taut set
  static constexpr double kSlackTolerance = 1e-9;  ///< stretch (per rest length) that makes taut
  /// Every edge joins consecutive vertices (chains): the rows are then banded and factorized in
  /// natural order, O(N); other graphs use Eigen's default (AMD) ordering.
  bool banded_ = false;
  /// Factorization for banded systems, kept so its storage is reused; copies start without one.
  struct BandedFactorization {
    BandedFactorization() = default;
    BandedFactorization(const BandedFactorization&) {}
    BandedFactorization& operator=(const BandedFactorization&) { return *this; }
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
        ldlt;
  };
  BandedFactorization banded_factorization_;
  /// Factorization for other graphs, its symbolic analysis kept while the pattern holds.
  PatternCachedLdlt general_factorization_;
  std::vector<int> vertex_row_;  ///< first row of each free vertex, -1 for supports
  std::vector<int> edge_row_;    ///< row of each taut edge, -1 otherwise
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double> matrix_;
  Eigen::VectorXd rhs_;
  Eigen::VectorXd solution_;
  std::vector<double> pass_multiplier_;  ///< multiplier of each edge in a pass's solution [kg*m]
  std::vector<double> stretch_;          ///< a pass's linearized stretch of slack edges [m]
  TautFrontier frontier_;                ///< takes in runs of slack edges at once
};

}  // namespace yarn_tearing
