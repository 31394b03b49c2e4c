#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/linalg/pattern_cached_ldlt.hpp"
#include "yarn_tearing/core/model/edge_incidence.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

/// One edge-by-edge linear system: which edges take part and the matrix's ingredients.
struct GramSystem {
  const std::vector<Eigen::Vector3d>* direction = nullptr;  ///< unit edge directions n_e
  const std::vector<double>* vertex_weight = nullptr;       ///< w_v per vertex
  const std::vector<std::uint8_t>* active = nullptr;        ///< edges taking part
  double regularization = 0.0;                              ///< lambda [-]
  const std::vector<double>* anchor = nullptr;              ///< x_anchor, or null for 0
  const std::vector<double>* diagonal_shift = nullptr;      ///< c_e added to G_ee, or null
};

/// Solves the edge-by-edge systems that both the constraint projection and the tension estimate
/// need: (G + lambda diag(G) + diag(c)) x = r + lambda diag(G) x_anchor, with the Gram matrix
///   G_ef = sum_v w_v g_ev . g_fv,   g_ea = -n_e, g_eb = +n_e   (n_e the unit edge direction),
/// restricted to the active edges. Inactive edges, and edges whose vertices all have weight 0,
/// get x_e = 0. Works on any edge graph (sparse LDLT); when every edge joins consecutive vertices
/// in increasing order (chains) it uses an O(N) tridiagonal solve instead.
class EdgeGramSolver {
 public:
  /// Learns the edge graph; call whenever edges are added (breaking does not change it).
  void setTopology(const EdgeSet& edges, std::size_t num_vertices);
  /// Forces the general sparse path even on chains (for testing both paths).
  void forceGeneralPath(bool force) { force_general_ = force; }
  /// True when the O(N) banded path is used.
  bool usesBandedPath() const { return is_chain_ && !force_general_; }
  /// The edges meeting at each vertex, as learnt by setTopology.
  const EdgeIncidence& incidence() const { return incidence_; }

  /// Solves in place: `rhs` in, x out.
  void solve(const EdgeSet& edges, const GramSystem& system, std::vector<double>& rhs);
  /// Solves in place for another right-hand side of the system the last solve() factorized
  /// (`system` unchanged since): solve()'s result without factorizing again (a few columns of
  /// the fast contact rows' Schur complement per pass).
  void resolve(const GramSystem& system, std::vector<double>& rhs);

 private:
  /// Fills diagonal_ (G_ee + lambda G_ee + c_e, or 1 for left-out edges) and gram_diagonal_.
  void assembleDiagonal(const EdgeSet& edges, const GramSystem& system);
  /// Adds the anchor term to `rhs`, and sets it to 0 for left-out edges.
  void prepareRightHandSide(const GramSystem& system, std::vector<double>& rhs) const;
  /// Thomas elimination of the banded matrix: pivot_, sweep_.
  void factorizeBanded(const EdgeSet& edges, const GramSystem& system);
  /// Solves in place with the last factorizeBanded().
  void substituteBanded(std::vector<double>& rhs) const;
  void solveGeneral(const EdgeSet& edges, const GramSystem& system, std::vector<double>& rhs);

  bool is_chain_ = false;
  bool force_general_ = false;
  EdgeIncidence incidence_;
  std::vector<double> diagonal_;        ///< assembled diagonal (1 for left-out edges)
  std::vector<std::uint8_t> included_;  ///< active edges with a movable vertex
  std::vector<double> upper_;           ///< banded: G_e,e+1
  std::vector<double> sweep_;           ///< banded: Thomas elimination factors
  std::vector<double> pivot_;           ///< banded: Thomas elimination pivots
  std::vector<double> gram_diagonal_;   ///< G_ee of the included edges (anchor term) [1/kg]
  std::vector<Eigen::Triplet<double>> triplets_;
  /// The general path's factorization, its symbolic analysis kept while the pattern holds.
  PatternCachedLdlt factorization_;
};

}  // namespace yarn_tearing
