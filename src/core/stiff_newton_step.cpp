#include "yarn_tearing/core/stiff_newton_step.hpp"

#include <algorithm>

namespace yarn_tearing {
namespace {

void addBlock(std::vector<Eigen::Triplet<double>>& triplets, int row, int col,
              const Eigen::Matrix3d& block) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) triplets.emplace_back(row + i, col + j, block(i, j));
  }
}

}  // namespace

bool StiffNewtonStep::solve(const std::vector<Eigen::Vector3d>& predicted,
                            const std::vector<double>& inverse_mass, const EdgeSet& edges,
                            const EdgeIncidence& incidence, const EdgeStretchState& stretch_state,
                            const std::vector<std::uint8_t>& taut,
                            const std::vector<Eigen::Vector3d>& position,
                            const std::vector<double>& multiplier) {
  // Rows in vertex order, each taut edge's row right after its later vertex's: a chain's system
  // is then banded, and the natural ordering factorizes it in O(N) without fill.
  const std::size_t n = position.size();
  vertex_row_.assign(n, -1);
  edge_row_.assign(edges.size(), -1);
  int rows = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (inverse_mass[v] > 0.0) {
      vertex_row_[v] = rows;
      rows += 3;
    }
    for (const std::uint32_t* it = incidence.begin(v); it != incidence.end(v); ++it) {
      const std::uint32_t e = *it;
      if (taut[e] && std::max(edges.vertex_a[e], edges.vertex_b[e]) == v) edge_row_[e] = rows++;
    }
  }
  triplets_.clear();
  rhs_.setZero(rows);
  for (std::size_t v = 0; v < n; ++v) {
    const int r = vertex_row_[v];
    if (r < 0) continue;
    const double mass = 1.0 / inverse_mass[v];
    for (int i = 0; i < 3; ++i) triplets_.emplace_back(r + i, r + i, mass);
    rhs_.segment<3>(r) = -mass * (position[v] - predicted[v]);
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (edge_row_[e] < 0) continue;
    const int ra = vertex_row_[edges.vertex_a[e]];
    const int rb = vertex_row_[edges.vertex_b[e]];
    const Eigen::Vector3d d = position[edges.vertex_b[e]] - position[edges.vertex_a[e]];
    const double length = d.norm();
    if (!(length > 0.0)) return false;
    const Eigen::Vector3d dir = d / length;
    // Geometric stiffness m_e Hess C_e = m_e (I - n n^T) / l on the (a, b) blocks.
    const Eigen::Matrix3d g =
        (multiplier[e] / length) * (Eigen::Matrix3d::Identity() - dir * dir.transpose());
    if (ra >= 0) addBlock(triplets_, ra, ra, g);
    if (rb >= 0) addBlock(triplets_, rb, rb, g);
    if (ra >= 0 && rb >= 0) {
      addBlock(triplets_, ra, rb, -g);
      addBlock(triplets_, rb, ra, -g);
    }
    const int re = edge_row_[e];
    for (int i = 0; i < 3; ++i) {
      if (ra >= 0) {
        triplets_.emplace_back(re, ra + i, -dir[i]);
        triplets_.emplace_back(ra + i, re, -dir[i]);
      }
      if (rb >= 0) {
        triplets_.emplace_back(re, rb + i, dir[i]);
        triplets_.emplace_back(rb + i, re, dir[i]);
      }
    }
    triplets_.emplace_back(re, re, -stretch_state.shift()[e]);
    rhs_[re] = -(length - stretch_state.baseLength()[e]);
  }
  matrix_.resize(rows, rows);
  matrix_.setFromTriplets(triplets_.begin(), triplets_.end());
  if (banded_) {
    banded_factorization_.ldlt.compute(matrix_);
    if (banded_factorization_.ldlt.info() != Eigen::Success) return false;
    solution_ = banded_factorization_.ldlt.solve(rhs_);
    return banded_factorization_.ldlt.info() == Eigen::Success && solution_.allFinite();
  }
  if (!general_factorization_.factorize(matrix_)) return false;
  solution_ = general_factorization_.solve(rhs_);
  return solution_.allFinite();
}

double StiffNewtonStep::linearizedStretch(const EdgeSet& edges,
                                          const EdgeStretchState& stretch_state, std::size_t e,
                                          const std::vector<Eigen::Vector3d>& position) const {
  const std::uint32_t a = edges.vertex_a[e];
  const std::uint32_t b = edges.vertex_b[e];
  const Eigen::Vector3d d = position[b] - position[a];
  const double length = d.norm();
  if (!(length > 0.0)) return 0.0;
  Eigen::Vector3d move = Eigen::Vector3d::Zero();
  if (vertex_row_[b] >= 0) move += solution_.segment<3>(vertex_row_[b]);
  if (vertex_row_[a] >= 0) move -= solution_.segment<3>(vertex_row_[a]);
  return length - stretch_state.baseLength()[e] + (d / length).dot(move);
}

void StiffNewtonStep::apply(const std::vector<Eigen::Vector3d>& predicted,
                            const std::vector<double>& inverse_mass, const EdgeSet& edges,
                            const EdgeIncidence& incidence, EdgeStretchState& stretch_state,
                            const std::vector<std::uint8_t>& movable,
                            std::vector<std::uint8_t>& taut, std::vector<Eigen::Vector3d>& position,
                            std::vector<double>& multiplier) {
  for (std::size_t e = 0; e < edges.size(); ++e) taut[e] = taut[e] & movable[e];
  banded_ = true;
  for (std::size_t e = 0; e < edges.size() && banded_; ++e) {
    banded_ = edges.vertex_b[e] == edges.vertex_a[e] + 1;
  }
  pass_multiplier_.resize(edges.size());
  stretch_.resize(edges.size());
  frontier_.reset(edges.size());
  // Block principal pivoting, as in the fast iterations: release the taut edges that would
  // push, take in the slack ones that the step would stretch (with the taut frontier), solve
  // again.
  for (int pass = 0;; ++pass) {
    if (!solve(predicted, inverse_mass, edges, incidence, stretch_state, taut, position,
               multiplier)) {
      return;
    }
    if (pass == kMaxPivotingPasses) break;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      pass_multiplier_[e] = edge_row_[e] >= 0 ? solution_[edge_row_[e]] : 0.0;
    }
    frontier_.beginPass(movable, taut, pass_multiplier_);
    bool changed = false;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (!movable[e]) continue;
      if (taut[e]) {
        if (pass_multiplier_[e] < 0.0 && frontier_.mayLeave(e)) {
          taut[e] = 0;
          frontier_.left(e);
          stretch_state.release(edges, e);
          changed = true;
        } else if (pass_multiplier_[e] > 0.0 && stretch_state.wouldSwitch(e, pass_multiplier_[e])) {
          stretch_state.settle(edges, e, pass_multiplier_[e]);
          changed = true;
        }
        continue;
      }
      stretch_[e] = linearizedStretch(edges, stretch_state, e, position);
      if (stretch_[e] > kSlackTolerance * edges.rest_length[e]) {
        taut[e] = 1;
        frontier_.joined(e);
        changed = true;
      }
    }
    if (!changed) break;
    frontier_.grow(edges, incidence, movable, stretch_, taut);
  }
  for (std::size_t v = 0; v < position.size(); ++v) {
    if (vertex_row_[v] >= 0) position[v] += solution_.segment<3>(vertex_row_[v]);
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    multiplier[e] = edge_row_[e] >= 0 ? std::max(solution_[edge_row_[e]], 0.0) : 0.0;
  }
}

}  // namespace yarn_tearing
