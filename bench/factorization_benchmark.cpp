// The kernels a tearing fabric's Newton systems can be factorized by, on one such system: this
// package's two (Eigen's simplicial LDL^T and SupernodalLdlt, on the KKT system in AMD order, as
// SparseLdlt runs them) against CHOLMOD's supernodal Cholesky of the system's Schur complement
// onto the vertices, which is positive definite (built where Debian's libsuitesparse-dev is
// installed).
// Run: build/core/yarn_tearing_bench --benchmark_filter='BM_FabricNewtonFactorization'
#include <benchmark/benchmark.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <limits>
#include <map>
#include <vector>

#ifdef YARN_TEARING_BENCH_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include "bench_support.hpp"
#include "yarn_tearing/core/linalg/supernodal_ldlt.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// The KKT matrix's blocks.
struct NewtonBlocks {
  SparseMatrix hessian;   ///< M + G, both triangles [kg]
  SparseMatrix jacobian;  ///< J, an edge a row [-]
  Eigen::VectorXd shift;  ///< S's diagonal [1/kg]
};

/// A fabric's Newton system over its taut edges (those under tension): the KKT matrix
/// [[M + G, J^T], [J, -S]] (M the free vertices' masses, G the edges' geometric stiffness, J the
/// edges' directions, S their elastic compliances L / (E A) over dt^2) and its Schur complement
/// onto the vertices, M + G + J^T S^-1 J.
struct FabricNewtonSystem {
  NewtonBlocks blocks;
  SparseMatrix kkt;    ///< both triangles; vertex rows [kg], edge rows [1/kg]
  SparseMatrix schur;  ///< both triangles [kg]
};

/// The first of each free vertex's three rows, -1 for a support [-].
std::vector<int> vertexRows(const VertexSet& vertices, int& rows) {
  std::vector<int> row(vertices.size(), -1);
  rows = 0;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (vertices.isSupport(v)) continue;
    row[v] = rows;
    rows += 3;
  }
  return row;
}

/// The blocks of `scene`'s system, its yarns' E A `stiffness` [N], for a step of `time_step` [s].
NewtonBlocks newtonBlocks(const Scene& scene, double stiffness, double time_step) {
  const VertexSet& vertices = scene.vertices;
  const EdgeSet& edges = scene.edges;
  const double dt2 = time_step * time_step;
  int vertex_rows = 0;
  const std::vector<int> row = vertexRows(vertices, vertex_rows);
  std::vector<Eigen::Triplet<double>> hessian;
  std::vector<Eigen::Triplet<double>> jacobian;
  std::vector<double> shift;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    for (int i = 0; i < 3 && row[v] >= 0; ++i) {
      hessian.emplace_back(row[v] + i, row[v] + i, vertices.mass[v]);
    }
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int ra = row[edges.vertex_a[e]];
    const int rb = row[edges.vertex_b[e]];
    if (!edges.intact(e) || !(edges.tension[e] > 0.0) || (ra < 0 && rb < 0)) continue;
    const Eigen::Vector3d d =
        vertices.position[edges.vertex_b[e]] - vertices.position[edges.vertex_a[e]];
    const double length = d.norm();
    const Eigen::Vector3d n = d / length;
    // m_e Hess C_e = m_e (I - n n^T) / l, m_e = T dt^2 [kg m].
    const Eigen::Matrix3d g =
        (edges.tension[e] * dt2 / length) * (Eigen::Matrix3d::Identity() - n * n.transpose());
    const auto block = [&](int r, int c, double sign) {
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) hessian.emplace_back(r + i, c + j, sign * g(i, j));
      }
    };
    if (ra >= 0) block(ra, ra, 1.0);
    if (rb >= 0) block(rb, rb, 1.0);
    if (ra >= 0 && rb >= 0) {
      block(ra, rb, -1.0);
      block(rb, ra, -1.0);
    }
    const int re = static_cast<int>(shift.size());
    for (int i = 0; i < 3; ++i) {
      if (ra >= 0) jacobian.emplace_back(re, ra + i, -n[i]);
      if (rb >= 0) jacobian.emplace_back(re, rb + i, n[i]);
    }
    shift.push_back(edges.rest_length[e] / (stiffness * dt2));
  }
  const int edge_rows = static_cast<int>(shift.size());
  NewtonBlocks blocks;
  blocks.hessian.resize(vertex_rows, vertex_rows);
  blocks.hessian.setFromTriplets(hessian.begin(), hessian.end());
  blocks.jacobian.resize(edge_rows, vertex_rows);
  blocks.jacobian.setFromTriplets(jacobian.begin(), jacobian.end());
  blocks.shift = Eigen::Map<const Eigen::VectorXd>(shift.data(), edge_rows);
  return blocks;
}

/// [[M + G, J^T], [J, -S]], both triangles.
SparseMatrix kktMatrix(const NewtonBlocks& blocks) {
  const Eigen::Index vertex_rows = blocks.hessian.rows();
  const Eigen::Index edge_rows = blocks.jacobian.rows();
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index k = 0; k < blocks.hessian.outerSize(); ++k) {
    for (SparseMatrix::InnerIterator it(blocks.hessian, k); it; ++it) {
      entries.emplace_back(it.row(), it.col(), it.value());
    }
  }
  for (Eigen::Index k = 0; k < blocks.jacobian.outerSize(); ++k) {
    for (SparseMatrix::InnerIterator it(blocks.jacobian, k); it; ++it) {
      entries.emplace_back(vertex_rows + it.row(), it.col(), it.value());
      entries.emplace_back(it.col(), vertex_rows + it.row(), it.value());
    }
  }
  for (Eigen::Index e = 0; e < edge_rows; ++e) {
    entries.emplace_back(vertex_rows + e, vertex_rows + e, -blocks.shift[e]);
  }
  SparseMatrix kkt(vertex_rows + edge_rows, vertex_rows + edge_rows);
  kkt.setFromTriplets(entries.begin(), entries.end());
  return kkt;
}

/// M + G + J^T S^-1 J, both triangles.
SparseMatrix schurComplement(const NewtonBlocks& blocks) {
  const Eigen::VectorXd inverse_shift = blocks.shift.cwiseInverse();
  SparseMatrix schur = blocks.hessian + SparseMatrix(blocks.jacobian.transpose() *
                                                     inverse_shift.asDiagonal() * blocks.jacobian);
  schur.makeCompressed();
  return schur;
}

/// The system of `scene`'s fabric at its current positions and tensions, its yarns of Young's
/// modulus `youngs_modulus` [Pa] and radius `radius` [m], for a step of `time_step` [s].
FabricNewtonSystem fabricNewtonSystem(const Scene& scene, double youngs_modulus, double radius,
                                      double time_step) {
  const double stiffness = youngs_modulus * EIGEN_PI * radius * radius;  // E A [N]
  const NewtonBlocks blocks = newtonBlocks(scene, stiffness, time_step);
  return FabricNewtonSystem{blocks, kktMatrix(blocks), schurComplement(blocks)};
}

using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

/// A symmetric matrix in its AMD order, as PatternCachedLdlt hands it to SparseLdlt.
struct AmdOrdered {
  SparseMatrix upper;       ///< the upper triangle of P A P^T
  Permutation permutation;  ///< P
};

/// `matrix` (both triangles given) in its AMD order.
AmdOrdered amdOrdered(const SparseMatrix& matrix) {
  Permutation inverse;
  Eigen::AMDOrdering<int>()(matrix, inverse);
  AmdOrdered ordered;
  ordered.permutation = inverse.inverse();
  SparseMatrix permuted;
  permuted = matrix.twistedBy(ordered.permutation);
  ordered.upper = permuted.triangularView<Eigen::Upper>();
  ordered.upper.makeCompressed();
  return ordered;
}

/// The Newton system of BM_FabricTearing's trouser tear of size `side` [-] at its first tear,
/// built once per size (the benchmark library calls a case several times).
const FabricNewtonSystem& trouserTearSystem(int side) {
  static std::map<int, FabricNewtonSystem> systems;
  const auto found = systems.find(side);
  if (found != systems.end()) return found->second;
  TrouserTear tear(side);
  Simulator& sim = tear.start();
  while (!tornOrPast(sim, 2.0)) tear.drive(sim);
  const YarnSpec yarn = TrouserTear::spec(side).warp;
  return systems[side] = fabricNewtonSystem(sim.scene(), yarn.material.curve.youngsModulus(),
                                            yarn.radius, sim.parameters().time_step);
}

/// The largest relative residual accepted of a kernel's solve: the kernels are timed on the
/// system they solve [-].
constexpr double kMostResidual = 1e-8;

/// Times `factorize()` (true when it succeeded) over `state`'s iterations; true when each did.
template <typename Factorize>
bool timeFactorizations(benchmark::State& state, const Factorize& factorize) {
  bool factorized = true;
  for (auto _ : state) factorized = factorize() && factorized;
  return factorized;
}

/// The KKT system's solution for `rhs` from the Schur complement's (`solve_schur`): the vertex
/// moves from (M + G + J^T S^-1 J) x = f + J^T S^-1 r, the edge rows' multipliers
/// S^-1 (J x - r).
template <typename SolveSchur>
Eigen::VectorXd kktFromSchur(const NewtonBlocks& blocks, const Eigen::VectorXd& rhs,
                             const SolveSchur& solve_schur) {
  const Eigen::Index n = blocks.hessian.rows();
  const Eigen::Index q = blocks.jacobian.rows();
  const Eigen::VectorXd scaled = rhs.tail(q).cwiseQuotient(blocks.shift);
  const Eigen::VectorXd moves =
      solve_schur(Eigen::VectorXd(rhs.head(n) + blocks.jacobian.transpose() * scaled));
  Eigen::VectorXd solution(n + q);
  solution << moves, (blocks.jacobian * moves).cwiseQuotient(blocks.shift) - scaled;
  return solution;
}

/// Kernels, the second argument: 0 Eigen's simplicial LDL^T and 1 SupernodalLdlt, each on the KKT
/// system in AMD order; 2 CHOLMOD's supernodal Cholesky of the Schur complement (its own order);
/// 3 SupernodalLdlt as 1 on two threads (SupernodalLdlt::setThreads).
/// `rows` is the factorized system's size [-]; `cost` the KKT factor's sum over its columns of
/// the squared nonzeros below the diagonal (kernel 1), CHOLMOD's flop count (kernel 2) [-];
/// `residual` the KKT system's relative residual |K x - b| / |b| of one solve [-].
void BM_FabricNewtonFactorization(benchmark::State& state) {
  const FabricNewtonSystem& system = trouserTearSystem(static_cast<int>(state.range(0)));
  const AmdOrdered ordered = amdOrdered(system.kkt);
  const Permutation& p = ordered.permutation;
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(system.kkt.rows());
  Eigen::VectorXd solution;
  bool factorized = false;
  switch (state.range(1)) {
    case 0: {
      Eigen::SimplicialLDLT<SparseMatrix, Eigen::Upper, Eigen::NaturalOrdering<int>> ldlt;
      ldlt.analyzePattern(ordered.upper);
      factorized = timeFactorizations(state, [&] {
        ldlt.factorize(ordered.upper);
        return ldlt.info() == Eigen::Success;
      });
      solution = p.transpose() * Eigen::VectorXd(ldlt.solve(Eigen::VectorXd(p * rhs)));
      state.counters["rows"] = static_cast<double>(ordered.upper.rows());
      break;
    }
    case 1:
    case 3: {
      SupernodalLdlt ldlt;
      ldlt.setThreads(state.range(1) == 3 ? 2 : 1);
      ldlt.analyzePattern(ordered.upper);
      factorized = timeFactorizations(state, [&] { return ldlt.factorize(ordered.upper); });
      Eigen::VectorXd permuted = p * rhs;
      ldlt.solveInPlace(permuted);
      solution = p.transpose() * permuted;
      state.counters["rows"] = static_cast<double>(ordered.upper.rows());
      state.counters["cost"] = ldlt.factorizationCost();
      break;
    }
    default: {
#ifdef YARN_TEARING_BENCH_CHOLMOD
      Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
      llt.analyzePattern(system.schur);
      factorized = timeFactorizations(state, [&] {
        llt.factorize(system.schur);
        return llt.info() == Eigen::Success;
      });
      solution = kktFromSchur(system.blocks, rhs, [&llt](const Eigen::VectorXd& b) {
        return Eigen::VectorXd(llt.solve(b));
      });
      state.counters["rows"] = static_cast<double>(system.schur.rows());
      state.counters["cost"] = llt.cholmod().fl;
#endif
    }
  }
  const double residual = solution.size() == rhs.size()
                              ? (system.kkt * solution - rhs).norm() / rhs.norm()
                              : std::numeric_limits<double>::infinity();
  state.counters["residual"] = residual;
  if (!factorized) state.SkipWithError("a factorization failed");
  if (!(residual <= kMostResidual)) state.SkipWithError("the solve misses its system");
}

BENCHMARK(BM_FabricNewtonFactorization)
    ->Args({32, 0})
    ->Args({32, 1})
#ifdef YARN_TEARING_BENCH_CHOLMOD
    ->Args({32, 2})
#endif
    ->Args({32, 3})
    ->Args({64, 0})
    ->Args({64, 1})
#ifdef YARN_TEARING_BENCH_CHOLMOD
    ->Args({64, 2})
#endif
    ->Args({64, 3})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace yarn_tearing
