// BandedLdlt on a chain's quasi-definite Newton system: the solution of a dense solve, its
// matrix product, and a zero pivot reported.
#include "yarn_tearing/core/linalg/banded_ldlt.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace yarn_tearing::test {
namespace {

/// `n` vertices of mass 1 + 0.1 v in a chain, three rows each, an edge row after each later
/// vertex (gradient along a tilted unit direction, compliance 1e-3, a geometric stiffness block
/// 0.5 (I - d d^T) between its vertices), laid out as StiffNewtonStep lays out a chain.
std::vector<Eigen::Triplet<double>> chainSystem(int n, int& rows) {
  std::vector<Eigen::Triplet<double>> entries;
  const Eigen::Vector3d d = Eigen::Vector3d(1.0, 0.2, -0.3).normalized();
  const Eigen::Matrix3d g = 0.5 * (Eigen::Matrix3d::Identity() - d * d.transpose());
  std::vector<int> vertex_row(n);
  rows = 0;
  for (int v = 0; v < n; ++v) {
    vertex_row[v] = rows;
    rows += 3;
    for (int i = 0; i < 3; ++i)
      entries.emplace_back(vertex_row[v] + i, vertex_row[v] + i, 1.0 + 0.1 * v);
    if (v == 0) continue;
    const int ra = vertex_row[v - 1];
    const int rb = vertex_row[v];
    const int re = rows++;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        entries.emplace_back(ra + i, ra + j, g(i, j));
        entries.emplace_back(rb + i, rb + j, g(i, j));
        entries.emplace_back(ra + i, rb + j, -g(i, j));
        entries.emplace_back(rb + i, ra + j, -g(i, j));
      }
      entries.emplace_back(re, ra + i, -d[i]);
      entries.emplace_back(ra + i, re, -d[i]);
      entries.emplace_back(re, rb + i, d[i]);
      entries.emplace_back(rb + i, re, d[i]);
    }
    entries.emplace_back(re, re, -1e-3);
  }
  return entries;
}

Eigen::MatrixXd dense(const std::vector<Eigen::Triplet<double>>& entries, int rows) {
  Eigen::SparseMatrix<double> sparse(rows, rows);
  sparse.setFromTriplets(entries.begin(), entries.end());
  return Eigen::MatrixXd(sparse);
}

TEST(BandedLdlt, MatchesADenseSolveOfAChainSystem) {
  int rows = 0;
  const std::vector<Eigen::Triplet<double>> entries = chainSystem(30, rows);
  BandedLdlt ldlt;
  ASSERT_TRUE(ldlt.factorize(entries, rows));
  EXPECT_EQ(ldlt.halfBandwidth(), 7);  // an edge row to its earlier vertex's first row
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(rows, -1.0, 2.0);
  Eigen::VectorXd x;
  ldlt.solve(rhs, x);
  const Eigen::MatrixXd a = dense(entries, rows);
  const Eigen::VectorXd expected = a.partialPivLu().solve(rhs);
  EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-10 * expected.lpNorm<Eigen::Infinity>());
  Eigen::VectorXd product;
  ldlt.multiply(x, product);
  EXPECT_LT((product - a * x).lpNorm<Eigen::Infinity>(), 1e-12 * rhs.lpNorm<Eigen::Infinity>());
}

TEST(BandedLdlt, ReportsAZeroPivot) {
  std::vector<Eigen::Triplet<double>> entries = {
      {0, 0, 1.0}, {1, 0, 1.0}, {0, 1, 1.0}, {1, 1, 1.0}};
  BandedLdlt ldlt;
  EXPECT_FALSE(ldlt.factorize(entries, 2));
}

}  // namespace
}  // namespace yarn_tearing::test
