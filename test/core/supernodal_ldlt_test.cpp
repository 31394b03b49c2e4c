// SupernodalLdlt (and SparseLdlt choosing it) against a dense solve and Eigen's simplicial LDL^T:
// quasi-definite systems shaped like the Newton step's (a grid of vertex blocks joined by edge
// rows), a diagonal missing from the pattern, the same factor's nonzeros, a refactorization with
// new values, and a zero pivot; the same factor to the bit on two threads.
#include "yarn_tearing/core/linalg/supernodal_ldlt.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <cmath>

#include "yarn_tearing/core/linalg/pattern_cached_ldlt.hpp"
#include "yarn_tearing/core/linalg/sparse_ldlt.hpp"

namespace yarn_tearing::test {
namespace {

/// A Newton-step-like KKT matrix of a side x side grid of vertices (3 rows each: mass and a
/// geometric stiffness block towards each neighbour) joined by edge rows along the grid lines
/// (unit direction couplings, compliance -1e-6 on the diagonal). `scale` varies the values.
Eigen::SparseMatrix<double> gridSystem(int side, double scale) {
  const int vertices = side * side;
  std::vector<Eigen::Triplet<double>> entries;
  int row = 3 * vertices;
  const auto vertex = [side](int r, int c) { return 3 * (r * side + c); };
  for (int v = 0; v < vertices; ++v) {
    for (int i = 0; i < 3; ++i) entries.emplace_back(3 * v + i, 3 * v + i, 1.0 + 0.01 * v);
  }
  for (int r = 0; r < side; ++r) {
    for (int c = 0; c < side; ++c) {
      for (int direction = 0; direction < 2; ++direction) {
        const int r2 = r + direction;
        const int c2 = c + 1 - direction;
        if (r2 >= side || c2 >= side) continue;
        const int a = vertex(r, c);
        const int b = vertex(r2, c2);
        const Eigen::Vector3d d =
            Eigen::Vector3d(1.0 - direction, direction, 0.1 * scale).normalized();
        const Eigen::Matrix3d g = 0.5 * scale * (Eigen::Matrix3d::Identity() - d * d.transpose());
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            entries.emplace_back(a + i, a + j, g(i, j));
            entries.emplace_back(b + i, b + j, g(i, j));
            entries.emplace_back(a + i, b + j, -g(i, j));
            entries.emplace_back(b + i, a + j, -g(i, j));
          }
          entries.emplace_back(row, a + i, -d[i]);
          entries.emplace_back(a + i, row, -d[i]);
          entries.emplace_back(row, b + i, d[i]);
          entries.emplace_back(b + i, row, d[i]);
        }
        entries.emplace_back(row, row, -1e-6);
        ++row;
      }
    }
  }
  Eigen::SparseMatrix<double> full(row, row);
  full.setFromTriplets(entries.begin(), entries.end());
  return full;
}

/// The upper triangle of P A P^T for an AMD ordering P, as PatternCachedLdlt passes it.
Eigen::SparseMatrix<double> orderedUpper(const Eigen::SparseMatrix<double>& full) {
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
  Eigen::AMDOrdering<int>()(full, inverse);
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation =
      inverse.inverse();
  Eigen::SparseMatrix<double> permuted;
  permuted = full.twistedBy(permutation);
  Eigen::SparseMatrix<double> upper = permuted.triangularView<Eigen::Upper>();
  upper.makeCompressed();
  return upper;
}

/// The normwise backward error |A x - b| / (|A| |x| + |b|) (infinity norms) of a solution x.
double backwardError(const Eigen::SparseMatrix<double>& upper, const Eigen::VectorXd& x,
                     const Eigen::VectorXd& b) {
  const Eigen::SparseMatrix<double> full = upper.selfadjointView<Eigen::Upper>();
  double norm = 0.0;  // the largest absolute row sum
  const Eigen::VectorXd row_sums = full.cwiseAbs() * Eigen::VectorXd::Ones(full.cols());
  norm = row_sums.maxCoeff();
  return (full * x - b).lpNorm<Eigen::Infinity>() /
         (norm * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
}

/// The backward error of Eigen's simplicial LDL^T (the same elimination, unpivoted, summed in
/// another order) on the same system. Without pivoting the elimination's growth, about the
/// inverse of the edge rows' compliance here, sets both errors far above the round-off.
double simplicialBackwardError(const Eigen::SparseMatrix<double>& upper, const Eigen::VectorXd& b) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper, Eigen::NaturalOrdering<int>>
      simplicial(upper);
  return backwardError(upper, simplicial.solve(b), b);
}

/// Round-off of the same elimination in another summation order: within this factor of the
/// simplicial one's [-].
constexpr double kSameRoundOff = 4.0;

/// Solves upper's system for b with `ldlt` analysed and factorized on it, and checks the
/// solution against `expected` (1e-10 relative) and its backward error against the simplicial
/// one's.
void expectSolves(SupernodalLdlt& ldlt, const Eigen::SparseMatrix<double>& upper,
                  const Eigen::VectorXd& b, const Eigen::VectorXd& expected) {
  ASSERT_TRUE(ldlt.analyzePattern(upper));
  ASSERT_TRUE(ldlt.factorize(upper));
  Eigen::VectorXd x = b;
  ldlt.solveInPlace(x);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
  EXPECT_LT(backwardError(upper, x, b), kSameRoundOff * simplicialBackwardError(upper, b));
}

TEST(SupernodalLdlt, SolvesAGridKktSystemAsADenseSolve) {
  const Eigen::SparseMatrix<double> upper = orderedUpper(gridSystem(8, 1.0));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(upper.rows(), -1.0, 2.0);
  const Eigen::SparseMatrix<double> full = upper.selfadjointView<Eigen::Upper>();
  const Eigen::MatrixXd dense(full);
  SupernodalLdlt ldlt;
  expectSolves(ldlt, upper, b, dense.partialPivLu().solve(b));
  // Fewer supernodes than columns: vertex blocks and separators share them.
  EXPECT_LT(ldlt.supernodes(), upper.rows() / 2);
}

TEST(SupernodalLdlt, HasTheSimplicialFactorsNonzerosAndSolution) {
  const Eigen::SparseMatrix<double> upper = orderedUpper(gridSystem(24, 1.0));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper, Eigen::NaturalOrdering<int>>
      simplicial(upper);
  ASSERT_EQ(simplicial.info(), Eigen::Success);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(upper.rows(), 3.0, -1.0);
  SupernodalLdlt ldlt;
  expectSolves(ldlt, upper, b, simplicial.solve(b));
  EXPECT_EQ(ldlt.factorNonZeros(), simplicial.matrixL().nestedExpression().nonZeros());
}

TEST(SupernodalLdlt, RefactorizesNewValuesOfTheSamePattern) {
  const Eigen::SparseMatrix<double> first = orderedUpper(gridSystem(12, 1.0));
  SupernodalLdlt ldlt;
  ASSERT_TRUE(ldlt.analyzePattern(first));
  ASSERT_TRUE(ldlt.factorize(first));
  // The same ordering and pattern, other values.
  Eigen::SparseMatrix<double> second = first;
  for (Eigen::Index k = 0; k < second.nonZeros(); ++k) {
    second.valuePtr()[k] *= 1.0 + 0.5 * std::sin(static_cast<double>(k));
  }
  ASSERT_TRUE(ldlt.factorize(second));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(second.rows(), -2.0, 1.0);
  Eigen::VectorXd x = b;
  ldlt.solveInPlace(x);
  EXPECT_LT(backwardError(second, x, b), kSameRoundOff * simplicialBackwardError(second, b));
}

TEST(SupernodalLdlt, TakesAPatternWithoutSomeDiagonalEntries) {
  // A KKT system with edge rows of zero compliance: their diagonal is not in the pattern, and
  // their pivots come from the elimination of the vertex rows.
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < 4; ++i) entries.emplace_back(i, i, 2.0 + i);
  for (int e = 0; e < 3; ++e) {
    entries.emplace_back(e, 4 + e, -1.0);
    entries.emplace_back(e + 1, 4 + e, 1.0);
  }
  Eigen::SparseMatrix<double> upper(7, 7);
  upper.setFromTriplets(entries.begin(), entries.end());
  upper.makeCompressed();
  SupernodalLdlt ldlt;
  ASSERT_TRUE(ldlt.analyzePattern(upper));
  ASSERT_TRUE(ldlt.factorize(upper));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(7, 1.0, 2.0);
  Eigen::VectorXd x = b;
  ldlt.solveInPlace(x);
  EXPECT_LT(backwardError(upper, x, b), 1e-15);  // no compliance: the round-off
}

TEST(SupernodalLdlt, RefusesAZeroPivotAndEntriesBelowTheDiagonal) {
  Eigen::SparseMatrix<double> singular(2, 2);
  singular.insert(0, 0) = 0.0;
  singular.insert(0, 1) = 1.0;
  singular.insert(1, 1) = 1.0;
  singular.makeCompressed();
  SupernodalLdlt ldlt;
  ASSERT_TRUE(ldlt.analyzePattern(singular));
  EXPECT_FALSE(ldlt.factorize(singular));
  Eigen::SparseMatrix<double> lower(2, 2);
  lower.insert(1, 0) = 1.0;
  lower.makeCompressed();
  EXPECT_FALSE(ldlt.analyzePattern(lower));
}

/// Analyses `upper` with `one` on one thread and `two` on two, whose split puts subtrees on both
/// threads and leaves the top separators for after them.
void analyzeOnOneAndTwoThreads(const Eigen::SparseMatrix<double>& upper, SupernodalLdlt& one,
                               SupernodalLdlt& two) {
  two.setThreads(2);
  ASSERT_TRUE(one.analyzePattern(upper));
  ASSERT_TRUE(two.analyzePattern(upper));
  ASSERT_TRUE(two.schedule().split());
  EXPECT_FALSE(two.schedule().top.empty());
  EXPECT_LT(two.schedule().time_share, 0.9);
}

TEST(SupernodalLdlt, FactorizesToTheSameBitsOnTwoThreads) {
  const Eigen::SparseMatrix<double> first = orderedUpper(gridSystem(24, 1.0));
  SupernodalLdlt one;
  SupernodalLdlt two;
  ASSERT_NO_FATAL_FAILURE(analyzeOnOneAndTwoThreads(first, one, two));
  Eigen::SparseMatrix<double> second = first;
  for (Eigen::Index k = 0; k < second.nonZeros(); ++k) {
    second.valuePtr()[k] *= 1.0 + 0.5 * std::cos(static_cast<double>(k));
  }
  const Eigen::SparseMatrix<double>* systems[] = {&first, &second};
  for (const Eigen::SparseMatrix<double>* upper : systems) {
    ASSERT_TRUE(one.factorize(*upper));
    ASSERT_TRUE(two.factorize(*upper));
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(upper->rows(), -1.0, 3.0);
    Eigen::VectorXd x_one = b;
    Eigen::VectorXd x_two = b;
    one.solveInPlace(x_one);
    two.solveInPlace(x_two);
    EXPECT_LT(backwardError(*upper, x_two, b), kSameRoundOff * simplicialBackwardError(*upper, b));
    for (Eigen::Index i = 0; i < b.size(); ++i) ASSERT_EQ(x_one[i], x_two[i]) << "row " << i;
  }
}

TEST(SupernodalLdlt, RefusesAZeroPivotOnTwoThreadsWhereOneDoes) {
  const Eigen::SparseMatrix<double> upper = orderedUpper(gridSystem(16, 1.0));
  SupernodalLdlt one;
  SupernodalLdlt two;
  ASSERT_NO_FATAL_FAILURE(analyzeOnOneAndTwoThreads(upper, one, two));
  // A zero diagonal entry: a zero pivot where its column is a leaf of the elimination tree,
  // whichever thread eliminates it.
  int refused = 0;
  for (Eigen::Index j = 0; j < upper.cols(); j += 3) {
    Eigen::SparseMatrix<double> trial = upper;
    trial.coeffRef(j, j) = 0.0;
    const bool factorized = one.factorize(trial);
    EXPECT_EQ(two.factorize(trial), factorized) << "column " << j;
    refused += factorized ? 0 : 1;
  }
  EXPECT_GT(refused, 10);
  // Both take the system again after a refusal.
  EXPECT_TRUE(two.factorize(upper));
}

}  // namespace
}  // namespace yarn_tearing::test

namespace yarn_tearing::test {
namespace {

TEST(SparseLdlt, ChoosesTheSupernodalKernelForDenseFrontsOnly) {
  // A 40 x 40 grid's Newton-like system has the 64 x 64 trouser tear's dense fronts; an 8 x 8
  // one's are small.
  for (const int side : {8, 40}) {
    const Eigen::SparseMatrix<double> upper = orderedUpper(gridSystem(side, 1.0));
    SupernodalLdlt supernodal;
    ASSERT_TRUE(supernodal.analyzePattern(upper));
    const bool dense = supernodal.factorizationCost() >= SparseLdlt::kSupernodalCost;
    EXPECT_EQ(dense, side == 40);
    SparseLdlt ldlt;
    ASSERT_TRUE(ldlt.analyzePattern(upper));
    EXPECT_EQ(ldlt.supernodal(), dense);
    ASSERT_TRUE(ldlt.factorize(upper));
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(upper.rows(), -1.0, 1.0);
    Eigen::VectorXd x = b;
    ldlt.solveInPlace(x);
    EXPECT_LT(backwardError(upper, x, b), kSameRoundOff * simplicialBackwardError(upper, b));
    // The kernels agree on the cost.
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper, Eigen::NaturalOrdering<int>>
        simplicial(upper);
    const Eigen::VectorXd column_counts =
        Eigen::Map<const Eigen::VectorXi>(
            simplicial.matrixL().nestedExpression().outerIndexPtr() + 1, upper.rows())
            .cast<double>() -
        Eigen::Map<const Eigen::VectorXi>(simplicial.matrixL().nestedExpression().outerIndexPtr(),
                                          upper.rows())
            .cast<double>();
    EXPECT_DOUBLE_EQ(supernodal.factorizationCost(), column_counts.squaredNorm());
  }
}

TEST(SparseLdlt, HandsBackToTheSimplicialKernelOnlyBelowItsLowerCost) {
  // A 40 x 40 grid takes the supernodal kernel; a 8 x 8 one, far below kSimplicialCost, hands it
  // back, and a 40 x 40 one takes it again; each solved within the simplicial kernel's error.
  SparseLdlt ldlt;
  for (const int side : {40, 8, 40}) {
    const Eigen::SparseMatrix<double> upper = orderedUpper(gridSystem(side, 1.0));
    ASSERT_TRUE(ldlt.analyzePattern(upper));
    EXPECT_EQ(ldlt.supernodal(), side == 40);
    ASSERT_TRUE(ldlt.factorize(upper));
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(upper.rows(), 2.0, -1.0);
    Eigen::VectorXd x = b;
    ldlt.solveInPlace(x);
    EXPECT_LT(backwardError(upper, x, b), kSameRoundOff * simplicialBackwardError(upper, b));
  }
}

TEST(PatternCachedLdlt, SolvesTheSameOnTwoThreadsWithTheSupernodalKernel) {
  // The 40 x 40 grid's system takes the supernodal kernel (above); listed as a Newton step lists
  // its entries.
  const Eigen::SparseMatrix<double> full = gridSystem(40, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < full.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(full, j); it; ++it) {
      entries.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value());
    }
  }
  PatternCachedLdlt one;
  PatternCachedLdlt two;
  two.setThreads(2);
  ASSERT_TRUE(one.factorize(entries, full.rows()));
  ASSERT_TRUE(two.factorize(entries, full.rows()));
  // A copy keeps the thread count (a Simulator copied keeps its parameters).
  PatternCachedLdlt copy = two;
  ASSERT_TRUE(copy.factorize(entries, full.rows()));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(full.rows(), 2.0, -1.0);
  const Eigen::VectorXd x_one = one.solve(b);
  const Eigen::VectorXd x_two = two.solve(b);
  const Eigen::VectorXd x_copy = copy.solve(b);
  EXPECT_LT((full * x_two - b).norm(), 1e-6 * b.norm());
  for (Eigen::Index i = 0; i < b.size(); ++i) {
    ASSERT_EQ(x_one[i], x_two[i]) << "row " << i;
    ASSERT_EQ(x_one[i], x_copy[i]) << "row " << i;
  }
}

}  // namespace
}  // namespace yarn_tearing::test
