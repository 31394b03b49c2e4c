#include "yarn_tearing/core/edge_gram_solver.hpp"

namespace yarn_tearing {
namespace {

/// g_ev . g_fv / (n_e . n_f): +1 when v plays the same role (a or b) in both edges, else -1.
double roleSign(const EdgeSet& edges, std::size_t e, std::size_t f, std::uint32_t v) {
  const bool e_is_b = edges.vertex_b[e] == v;
  const bool f_is_b = edges.vertex_b[f] == v;
  return e_is_b == f_is_b ? 1.0 : -1.0;
}

double selfWeight(const EdgeSet& edges, const std::vector<double>& w, std::size_t e) {
  return w[edges.vertex_a[e]] + w[edges.vertex_b[e]];
}

}  // namespace

void EdgeGramSolver::setTopology(const EdgeSet& edges, std::size_t num_vertices) {
  is_chain_ = true;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const bool consecutive = edges.vertex_b[e] == edges.vertex_a[e] + 1;
    const bool increasing = e == 0 || edges.vertex_a[e] > edges.vertex_a[e - 1];
    if (!consecutive || !increasing) is_chain_ = false;
  }
  incidence_offset_.assign(num_vertices + 1, 0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    ++incidence_offset_[edges.vertex_a[e] + 1];
    ++incidence_offset_[edges.vertex_b[e] + 1];
  }
  for (std::size_t v = 0; v < num_vertices; ++v) incidence_offset_[v + 1] += incidence_offset_[v];
  incidence_edge_.assign(incidence_offset_.back(), 0);
  std::vector<std::uint32_t> fill(incidence_offset_.begin(), incidence_offset_.end() - 1);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    incidence_edge_[fill[edges.vertex_a[e]]++] = static_cast<std::uint32_t>(e);
    incidence_edge_[fill[edges.vertex_b[e]]++] = static_cast<std::uint32_t>(e);
  }
  diagonal_.resize(edges.size());
  upper_.resize(edges.size());
  sweep_.resize(edges.size());
}

void EdgeGramSolver::solve(const EdgeSet& edges, const std::vector<Eigen::Vector3d>& direction,
                           const std::vector<double>& vertex_weight,
                           const std::vector<std::uint8_t>& active, double regularization,
                           const std::vector<double>* anchor, std::vector<double>& rhs) {
  if (usesBandedPath()) {
    solveBanded(edges, direction, vertex_weight, active, regularization, anchor, rhs);
  } else {
    solveGeneral(edges, direction, vertex_weight, active, regularization, anchor, rhs);
  }
}

void EdgeGramSolver::solveBanded(const EdgeSet& edges,
                                 const std::vector<Eigen::Vector3d>& direction,
                                 const std::vector<double>& w,
                                 const std::vector<std::uint8_t>& active, double regularization,
                                 const std::vector<double>* anchor, std::vector<double>& rhs) {
  const std::size_t q = edges.size();
  for (std::size_t e = 0; e < q; ++e) {
    const double g = active[e] ? selfWeight(edges, w, e) : 0.0;
    if (g > 0.0) {
      diagonal_[e] = g * (1.0 + regularization);
      if (anchor != nullptr) rhs[e] += regularization * g * (*anchor)[e];
    } else {
      diagonal_[e] = 1.0;
      rhs[e] = 0.0;
    }
    const bool coupled = e + 1 < q && active[e] && active[e + 1] &&
                         edges.vertex_b[e] == edges.vertex_a[e + 1];
    upper_[e] = coupled ? -w[edges.vertex_b[e]] * direction[e].dot(direction[e + 1]) : 0.0;
  }
  // Thomas algorithm (the matrix is symmetric positive definite, no pivoting needed).
  double previous_sweep = 0.0;
  double previous_rhs = 0.0;
  for (std::size_t e = 0; e < q; ++e) {
    const double lower = e > 0 ? upper_[e - 1] : 0.0;
    const double pivot = diagonal_[e] - lower * previous_sweep;
    sweep_[e] = upper_[e] / pivot;
    rhs[e] = (rhs[e] - lower * previous_rhs) / pivot;
    previous_sweep = sweep_[e];
    previous_rhs = rhs[e];
  }
  for (std::size_t e = q; e-- > 1;) rhs[e - 1] -= sweep_[e - 1] * rhs[e];
}

void EdgeGramSolver::solveGeneral(const EdgeSet& edges,
                                  const std::vector<Eigen::Vector3d>& direction,
                                  const std::vector<double>& w,
                                  const std::vector<std::uint8_t>& active, double regularization,
                                  const std::vector<double>* anchor, std::vector<double>& rhs) {
  const std::size_t q = edges.size();
  triplets_.clear();
  for (std::size_t e = 0; e < q; ++e) {
    const double g = active[e] ? selfWeight(edges, w, e) : 0.0;
    if (!(g > 0.0)) {
      triplets_.emplace_back(e, e, 1.0);
      rhs[e] = 0.0;
      continue;
    }
    triplets_.emplace_back(e, e, g * (1.0 + regularization));
    if (anchor != nullptr) rhs[e] += regularization * g * (*anchor)[e];
    for (std::uint32_t v : {edges.vertex_a[e], edges.vertex_b[e]}) {
      if (w[v] == 0.0) continue;
      for (std::uint32_t k = incidence_offset_[v]; k < incidence_offset_[v + 1]; ++k) {
        const std::uint32_t f = incidence_edge_[k];
        if (f == e || !active[f] || !(selfWeight(edges, w, f) > 0.0)) continue;
        const double value = w[v] * roleSign(edges, e, f, v) * direction[e].dot(direction[f]);
        triplets_.emplace_back(e, f, value);
      }
    }
  }
  matrix_.resize(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(q));
  matrix_.setFromTriplets(triplets_.begin(), triplets_.end());
  ldlt_.compute(matrix_);
  Eigen::Map<Eigen::VectorXd> b(rhs.data(), static_cast<Eigen::Index>(q));
  const Eigen::VectorXd x = ldlt_.solve(b);
  b = x;
}

}  // namespace yarn_tearing
