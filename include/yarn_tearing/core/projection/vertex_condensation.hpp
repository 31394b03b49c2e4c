#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_incidence.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

/// Eliminates from a Newton system (StiffNewtonStep) the rows of the free vertices that no edge
/// stiffens: a vertex whose every edge with a row has no geometric stiffness (each end a support
/// or taking its start direction, or the edge idle) has the rows m_v dx_v + sum_e g_ev m_e = r_v,
/// so dx_v = w_v (r_v - sum_e g_ev m_e) exactly, and its edges' rows take the couplings
/// -w_v g_ev . g_fv and the right-hand side -w_v g_ev . r_v instead (g_ea = -n_e, g_eb = +n_e,
/// w_v = 1/m_v). What is left is the edges' rows and those of the stiffened vertices: a held
/// fabric's system shrinks from 3 rows a vertex plus one an edge to about one an edge.
class VertexCondensation {
 public:
  /// Chooses the vertices to eliminate and numbers the rows that stay. `vertex_row` is each
  /// vertex's first row (-1 for supports), `edge_row` each edge's row (-1 for none), `plain` per
  /// edge whether it has no geometric stiffness, `rows` the full system's size. Returns the
  /// number of eliminated vertices.
  std::size_t choose(const EdgeSet& edges, const EdgeIncidence& incidence,
                     const std::vector<int>& vertex_row, const std::vector<int>& edge_row,
                     const std::vector<std::uint8_t>& plain, int rows);
  /// Whether any vertex is eliminated.
  bool active() const { return !vertex_.empty(); }
  /// Rows of the reduced system [-].
  int reducedRows() const { return reduced_rows_; }
  /// The reduced row of full row `row`, -1 for an eliminated vertex's.
  int reducedRow(int row) const { return reduced_row_[static_cast<std::size_t>(row)]; }
  /// Calls add(row, col, value) (full rows) for the couplings the eliminated vertices leave
  /// between their edges' rows, in a fixed order: -w_v g_ev . g_fv for each eliminated vertex v
  /// and each pair of its edges (both orders, and each edge with itself). `direction` is each
  /// edge's unit direction in the system (0 for an idle edge) [-], `inverse_mass` w_v [1/kg].
  template <typename Add>
  void addCouplings(const std::vector<double>& inverse_mass,
                    const std::vector<Eigen::Vector3d>& direction, const Add& add) const {
    for (std::size_t k = 0; k < vertex_.size(); ++k) {
      const double w = inverse_mass[vertex_[k]];
      for (std::uint32_t i = start_[k]; i < start_[k + 1]; ++i) {
        const Eigen::Vector3d gi = sign_[i] * direction[edge_[i]];
        for (std::uint32_t j = start_[k]; j < start_[k + 1]; ++j) {
          add(row_[i], row_[j], -w * gi.dot(sign_[j] * direction[edge_[j]]));
        }
      }
    }
  }
  /// The reduced right-hand side of the full one (`direction`, `inverse_mass` as above).
  void condense(const Eigen::VectorXd& full, const std::vector<double>& inverse_mass,
                const std::vector<Eigen::Vector3d>& direction, Eigen::VectorXd& reduced) const;
  /// The full solution from the reduced one and the full right-hand side `full_rhs`.
  void expand(const Eigen::VectorXd& full_rhs, const Eigen::VectorXd& reduced,
              const std::vector<double>& inverse_mass,
              const std::vector<Eigen::Vector3d>& direction, Eigen::VectorXd& full) const;
  /// Per vertex: eliminated (1) or not, for telling whether two systems are laid out alike.
  const std::vector<std::uint8_t>& eliminated() const { return eliminated_; }

 private:
  std::vector<std::uint8_t> eliminated_;  ///< per vertex
  std::vector<int> reduced_row_;          ///< per full row: its reduced row, -1 if eliminated
  int reduced_rows_ = 0;
  std::vector<std::uint32_t> vertex_;  ///< the eliminated vertices
  std::vector<int> vertex_first_row_;  ///< their first full row
  std::vector<std::uint32_t> start_;   ///< where each one's edges start in edge_, row_, sign_
  std::vector<std::uint32_t> edge_;    ///< the edges with a row at an eliminated vertex
  std::vector<int> row_;               ///< their full rows
  std::vector<double> sign_;           ///< g_ev = sign n_e: +1 where v is the edge's b
};

}  // namespace yarn_tearing
