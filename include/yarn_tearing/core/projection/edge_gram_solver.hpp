#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/linalg/conjugate_gradients.hpp"
#include "yarn_tearing/core/linalg/pattern_cached_ldlt.hpp"
#include "yarn_tearing/core/linalg/tridiagonal_ldlt.hpp"
#include "yarn_tearing/core/model/edge_chains.hpp"
#include "yarn_tearing/core/model/edge_incidence.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/projection/chain_preconditioner.hpp"
#include "yarn_tearing/core/projection/gram_operator.hpp"

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
/// get x_e = 0. When every edge joins consecutive vertices in increasing order (chains) it is an
/// O(N) tridiagonal solve. On other edge graphs (woven fabrics) the unregularized systems of the
/// projection are solved by conjugate gradients (ConjugateGradients on the matrix-free
/// GramOperator) preconditioned by the yarns' own blocks (ChainPreconditioner), started from the
/// last solution, to a relative residual of kIterativeTolerance, from kIterativeEdges edges on
/// (a 64 x 64 fabric: 8,064); where that does not converge within kMostIterations, and for
/// regularized systems (the least-squares tension), a sparse LDL^T. Its matrix lists every pair
/// of edges that meet at a free vertex, the rows of edges not taking part idle
/// (PatternCachedLdlt::leaveOutIdleRows): while the taut set changes, as in every pivoting pass
/// of a flapping fabric's fast iterations, the listed pattern holds and only the entries in use
/// are analysed anew, in the same ordering.
class EdgeGramSolver {
 public:
  /// Learns the edge graph; call whenever edges are added (breaking does not change it).
  void setTopology(const EdgeSet& edges, std::size_t num_vertices);
  /// Forces the general sparse path even on chains (for testing both paths).
  void forceGeneralPath(bool force) { force_general_ = force; }
  /// Solves every system of a graph that is no chain by the sparse LDL^T, never by conjugate
  /// gradients (for testing both paths).
  void forceDirectSolves(bool force) { force_direct_ = force; }
  /// Threads the sparse factorization may use [-] (PatternCachedLdlt::setThreads).
  void setThreads(int threads) { factorization_.setThreads(threads); }
  /// True when the O(N) banded path is used.
  bool usesBandedPath() const { return is_chain_ && !force_general_; }
  /// True when the last solve() converged by conjugate gradients.
  bool lastSolveIterative() const { return last_iterative_; }
  /// The edges meeting at each vertex, as learnt by setTopology.
  const EdgeIncidence& incidence() const { return incidence_; }

  /// Solves in place: `rhs` in, x out.
  void solve(const EdgeSet& edges, const GramSystem& system, std::vector<double>& rhs);
  /// Solves in place for another right-hand side of the system the last solve() factorized
  /// (`system` unchanged since): solve()'s result without factorizing again (a few columns of
  /// the fast contact rows' Schur complement per pass).
  void resolve(const EdgeSet& edges, const GramSystem& system, std::vector<double>& rhs);

 private:
  /// Fills diagonal_ (G_ee + lambda G_ee + c_e, or 1 for left-out edges) and gram_diagonal_.
  void assembleDiagonal(const EdgeSet& edges, const GramSystem& system);
  /// Adds the anchor term to `rhs`, and sets it to 0 for left-out edges.
  void prepareRightHandSide(const GramSystem& system, std::vector<double>& rhs) const;
  /// Factorizes the chains' tridiagonal matrix (banded_).
  void factorizeBanded(const EdgeSet& edges, const GramSystem& system);
  /// Conjugate gradients from `guess` (or from 0 when it does not fit); false when they do not
  /// converge within kMostIterations (`rhs` then unchanged).
  bool solveIterative(const EdgeSet& edges, const GramSystem& system, std::vector<double>& rhs,
                      const std::vector<double>& guess);
  void solveGeneral(const EdgeSet& edges, const GramSystem& system, std::vector<double>& rhs);
  /// Lists each edge's couplings (couplings_, coupling_start_).
  void listCouplings(const EdgeSet& edges);

  /// Relative residual |b - A x| / |b| at which conjugate gradients stop [-]: far below the
  /// projection's constraint_tolerance, so the projection's iterates are those of an exact solve
  /// to within round-off of its own tests.
  static constexpr double kIterativeTolerance = 1e-11;
  /// Conjugate-gradient iterations after which a system is left to the sparse LDL^T [-].
  static constexpr int kMostIterations = 100;
  /// Edges from which conjugate gradients solve a graph that is no chain [-]: below, the sparse
  /// LDL^T of the small system costs less than the 10-30 iterations a flapping patch needs.
  static constexpr std::size_t kIterativeEdges = 4000;

  bool is_chain_ = false;
  bool force_general_ = false;
  bool force_direct_ = false;
  /// The last solve() was by conjugate gradients (resolve() then iterates as well).
  bool last_iterative_ = false;
  EdgeIncidence incidence_;
  EdgeChains chains_;
  ChainPreconditioner preconditioner_;
  std::vector<double> last_solution_;  ///< conjugate gradients' last solution (their next start)
  Eigen::VectorXd iterate_;            ///< conjugate gradients' iterate
  std::vector<Eigen::Vector3d> vertex_sum_;  ///< GramOperator's per-vertex scratch
  ConjugateGradients conjugate_gradients_;
  std::vector<double> diagonal_;        ///< assembled diagonal (1 for left-out edges)
  std::vector<std::uint8_t> included_;  ///< active edges with a movable vertex
  std::vector<double> upper_;           ///< banded: G_e,e+1
  TridiagonalLdlt banded_;              ///< banded: the chains' factorization
  std::vector<double> gram_diagonal_;   ///< G_ee of the included edges (anchor term) [1/kg]
  std::vector<Eigen::Triplet<double>> triplets_;
  /// The general path's factorization, its symbolic analysis kept while the pattern holds.
  PatternCachedLdlt factorization_;
  /// Another edge meeting an edge at one of its vertices: G_ef = w_v sign n_e . n_f.
  struct Coupling {
    std::uint32_t edge;    ///< f
    std::uint32_t vertex;  ///< v
    double sign;           ///< g_ev . g_fv / (n_e . n_f): +1 or -1
  };
  /// Each edge's couplings, in the order of its vertices and their incidence lists: edge e's are
  /// couplings_[coupling_start_[e] .. coupling_start_[e + 1]).
  std::vector<Coupling> couplings_;
  std::vector<std::uint32_t> coupling_start_;
};

}  // namespace yarn_tearing
