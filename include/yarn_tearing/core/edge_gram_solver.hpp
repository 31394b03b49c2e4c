#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/edge_set.hpp"

namespace yarn_tearing {

/// Solves the edge-by-edge systems that both the constraint projection and the tension estimate
/// need: (G + lambda diag(G)) x = r + lambda diag(G) x_anchor, with the Gram matrix
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

  /// Solves in place: `rhs` in, x out. `direction` is n_e per edge, `vertex_weight` w_v per
  /// vertex, `active` selects edges; `anchor` (may be null) is x_anchor.
  void solve(const EdgeSet& edges, const std::vector<Eigen::Vector3d>& direction,
             const std::vector<double>& vertex_weight, const std::vector<std::uint8_t>& active,
             double regularization, const std::vector<double>* anchor, std::vector<double>& rhs);

 private:
  void solveBanded(const EdgeSet& edges, const std::vector<Eigen::Vector3d>& direction,
                   const std::vector<double>& w, const std::vector<std::uint8_t>& active,
                   double regularization, const std::vector<double>* anchor,
                   std::vector<double>& rhs);
  void solveGeneral(const EdgeSet& edges, const std::vector<Eigen::Vector3d>& direction,
                    const std::vector<double>& w, const std::vector<std::uint8_t>& active,
                    double regularization, const std::vector<double>* anchor,
                    std::vector<double>& rhs);

  bool is_chain_ = false;
  bool force_general_ = false;
  std::vector<std::uint32_t> incidence_offset_;  ///< CSR offsets of vertex -> incident edges
  std::vector<std::uint32_t> incidence_edge_;    ///< CSR incident edges
  std::vector<double> diagonal_;                 ///< banded: G_ee
  std::vector<double> upper_;                    ///< banded: G_e,e+1
  std::vector<double> sweep_;                    ///< banded: Thomas elimination factors
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double> matrix_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
};

}  // namespace yarn_tearing
