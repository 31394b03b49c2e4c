#include "yarn_tearing/core/projection/edge_gram_solver.hpp"

#include <algorithm>

#include "yarn_tearing/core/projection/gram_operator.hpp"

namespace yarn_tearing {
namespace {

/// g_ev . g_fv / (n_e . n_f): +1 when v plays the same role (a or b) in both edges, else -1.
double roleSign(const EdgeSet& edges, std::size_t e, std::size_t f, std::uint32_t v) {
  const bool e_is_b = edges.vertex_b[e] == v;
  const bool f_is_b = edges.vertex_b[f] == v;
  return e_is_b == f_is_b ? 1.0 : -1.0;
}

}  // namespace

void EdgeGramSolver::setTopology(const EdgeSet& edges, std::size_t num_vertices) {
  is_chain_ = true;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const bool consecutive = edges.vertex_b[e] == edges.vertex_a[e] + 1;
    const bool increasing = e == 0 || edges.vertex_a[e] > edges.vertex_a[e - 1];
    if (!consecutive || !increasing) is_chain_ = false;
  }
  incidence_.build(edges, num_vertices);
  chains_.build(edges, incidence_);
  listCouplings(edges);
  diagonal_.resize(edges.size());
  included_.resize(edges.size());
  upper_.resize(edges.size());
  gram_diagonal_.resize(edges.size());
  last_solution_.clear();
}

void EdgeGramSolver::listCouplings(const EdgeSet& edges) {
  couplings_.clear();
  coupling_start_.assign(1, 0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    for (std::uint32_t v : {edges.vertex_a[e], edges.vertex_b[e]}) {
      for (const std::uint32_t* it = incidence_.begin(v); it != incidence_.end(v); ++it) {
        if (*it != e) couplings_.push_back({*it, v, roleSign(edges, e, *it, v)});
      }
    }
    coupling_start_.push_back(static_cast<std::uint32_t>(couplings_.size()));
  }
}

void EdgeGramSolver::solve(const EdgeSet& edges, const GramSystem& system,
                           std::vector<double>& rhs) {
  assembleDiagonal(edges, system);
  prepareRightHandSide(system, rhs);
  if (usesBandedPath()) {
    factorizeBanded(edges, system);
    banded_.solveInPlace(rhs.data());
    return;
  }
  last_iterative_ = !force_direct_ && system.regularization == 0.0 && system.anchor == nullptr &&
                    included_.size() >= kIterativeEdges;
  if (last_iterative_) {
    preconditioner_.factorize(edges, chains_, *system.direction, *system.vertex_weight, included_,
                              diagonal_);
    last_iterative_ = solveIterative(edges, system, rhs, last_solution_);
    if (last_iterative_) {
      last_solution_ = rhs;
      return;
    }
  }
  solveGeneral(edges, system, rhs);
}

void EdgeGramSolver::resolve(const EdgeSet& edges, const GramSystem& system,
                             std::vector<double>& rhs) {
  prepareRightHandSide(system, rhs);
  if (usesBandedPath()) {
    banded_.solveInPlace(rhs.data());
    return;
  }
  if (last_iterative_ && solveIterative(edges, system, rhs, {})) return;
  if (last_iterative_) {
    solveGeneral(edges, system, rhs);  // factorizes the system for the resolves that follow
    last_iterative_ = false;
    return;
  }
  Eigen::Map<Eigen::VectorXd> b(rhs.data(), static_cast<Eigen::Index>(included_.size()));
  const Eigen::VectorXd x = factorization_.solve(b);
  b = x;
}

bool EdgeGramSolver::solveIterative(const EdgeSet& edges, const GramSystem& system,
                                    std::vector<double>& rhs, const std::vector<double>& guess) {
  const auto q = static_cast<Eigen::Index>(included_.size());
  const GramOperator matrix(edges, *system.direction, *system.vertex_weight, included_, diagonal_,
                            gram_diagonal_, vertex_sum_);
  const Eigen::Map<const Eigen::VectorXd> b(rhs.data(), q);
  Eigen::VectorXd& x = iterate_;
  x.setZero(q);
  if (static_cast<Eigen::Index>(guess.size()) == q) {
    for (Eigen::Index e = 0; e < q; ++e) x[e] = included_[e] ? guess[e] : 0.0;
  }
  const auto multiply = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
    matrix.multiply(v, out);
  };
  const auto precondition = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
    preconditioner_.apply(v, out);
  };
  if (!conjugate_gradients_.solve(multiply, precondition, b, x, kIterativeTolerance,
                                  kMostIterations) ||
      !x.allFinite()) {
    return false;
  }
  Eigen::Map<Eigen::VectorXd>(rhs.data(), q) = x;
  return true;
}

void EdgeGramSolver::assembleDiagonal(const EdgeSet& edges, const GramSystem& system) {
  const std::vector<double>& w = *system.vertex_weight;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const double g = (*system.active)[e] ? w[edges.vertex_a[e]] + w[edges.vertex_b[e]] : 0.0;
    gram_diagonal_[e] = g;
    included_[e] = g > 0.0 ? 1 : 0;
    if (!included_[e]) {
      diagonal_[e] = 1.0;
      continue;
    }
    diagonal_[e] = g * (1.0 + system.regularization);
    if (system.diagonal_shift != nullptr) diagonal_[e] += (*system.diagonal_shift)[e];
  }
}

void EdgeGramSolver::prepareRightHandSide(const GramSystem& system,
                                          std::vector<double>& rhs) const {
  for (std::size_t e = 0; e < included_.size(); ++e) {
    if (!included_[e]) {
      rhs[e] = 0.0;
    } else if (system.anchor != nullptr) {
      rhs[e] += system.regularization * gram_diagonal_[e] * (*system.anchor)[e];
    }
  }
}

void EdgeGramSolver::factorizeBanded(const EdgeSet& edges, const GramSystem& system) {
  const std::vector<double>& w = *system.vertex_weight;
  const std::vector<Eigen::Vector3d>& n = *system.direction;
  const std::size_t q = edges.size();
  for (std::size_t e = 0; e < q; ++e) {
    const bool coupled =
        e + 1 < q && included_[e] && included_[e + 1] && edges.vertex_b[e] == edges.vertex_a[e + 1];
    upper_[e] = coupled ? -w[edges.vertex_b[e]] * n[e].dot(n[e + 1]) : 0.0;
  }
  banded_.factorize(diagonal_, upper_);
}

void EdgeGramSolver::solveGeneral(const EdgeSet& edges, const GramSystem& system,
                                  std::vector<double>& rhs) {
  const std::vector<double>& w = *system.vertex_weight;
  const std::vector<Eigen::Vector3d>& n = *system.direction;
  const std::size_t q = edges.size();
  // Every pair of edges that meet at a free vertex is listed, the rows of edges not included
  // idle: the pattern holds while the included edges change (PatternCachedLdlt::leaveOutIdleRows).
  // An idle row's entries are zeros: `skip(count, list_zeros)` passes over its `count` of them
  // (or lists them, through `list_zeros()`).
  const auto list = [&](const auto& add, const auto& skip) {
    for (std::size_t e = 0; e < q; ++e) {
      const int row = static_cast<int>(e);
      add(row, row, diagonal_[e]);
      const Coupling* first = couplings_.data() + coupling_start_[e];
      const Coupling* end = couplings_.data() + coupling_start_[e + 1];
      if (!included_[e]) {
        const auto count =
            std::count_if(first, end, [&](const Coupling& c) { return w[c.vertex] != 0.0; });
        skip(static_cast<std::size_t>(count), [&]() {
          for (const Coupling* c = first; c != end; ++c) {
            if (w[c->vertex] != 0.0) add(row, static_cast<int>(c->edge), 0.0);
          }
        });
        continue;
      }
      for (const Coupling* c = first; c != end; ++c) {
        if (w[c->vertex] == 0.0) continue;
        add(row, static_cast<int>(c->edge),
            included_[c->edge] ? w[c->vertex] * c->sign * n[e].dot(n[c->edge]) : 0.0);
      }
    }
  };
  factorization_.leaveOutIdleRows(&included_);
  // Straight into the analysed pattern while the free vertices stay the same.
  const Eigen::Index size = static_cast<Eigen::Index>(q);
  bool listed = factorization_.beginDirect(size);
  if (listed) {
    list([&](int row, int col,
             double value) { listed = listed && factorization_.addDirect(row, col, value); },
         [&](std::size_t count, const auto&) {
           listed = listed && factorization_.skipDirect(count);
         });
  }
  if (listed && factorization_.endDirect()) {
    factorization_.factorizeDirect();
  } else {
    triplets_.clear();
    list([&](int row, int col, double value) { triplets_.emplace_back(row, col, value); },
         [](std::size_t, const auto& list_zeros) { list_zeros(); });
    factorization_.factorize(triplets_, size);
  }
  Eigen::Map<Eigen::VectorXd> b(rhs.data(), static_cast<Eigen::Index>(q));
  const Eigen::VectorXd x = factorization_.solve(b);
  b = x;
}

}  // namespace yarn_tearing
