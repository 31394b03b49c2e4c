// PatternCachedLdlt leaving stored zeros out of the factorization (leaveOutZeros()): the same
// solution as with them, a factor without their fill, and a new analysis only when a nonzero
// falls outside the analysed one; entries added straight into the analysed pattern factorize as
// the same entries listed; with keepAnalyses(), a pattern that returns is not analysed again;
// with leaveOutIdleRows(), a pattern listed once holds while the rows in use change, zeros
// between rows in use are kept, and rows in use that settle get an ordering of their own.
#include "yarn_tearing/core/linalg/pattern_cached_ldlt.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

namespace yarn_tearing::test {
namespace {

/// A quasi-definite system shaped like a Newton step's: `n` unit masses in a ring (one row
/// each), each pair of neighbours joined by an edge row (gradient -1, +1, compliance 1e-3).
/// Edge rows with `idle` set list the same entries with zero couplings and -1 on the diagonal,
/// as the idle rows of slack edges do.
/// With `stride` > 1, edge e joins vertex e to vertex e + stride instead (as many entries,
/// another pattern).
std::vector<Eigen::Triplet<double>> ringSystem(int n, const std::vector<bool>& idle,
                                               int stride = 1) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int v = 0; v < n; ++v) entries.emplace_back(v, v, 1.0 + 0.1 * v);
  for (int e = 0; e < n; ++e) {
    const int row = n + e;
    const int a = e;
    const int b = (e + stride) % n;
    const double coupling = idle[e] ? 0.0 : 1.0;
    entries.emplace_back(row, a, -coupling);
    entries.emplace_back(a, row, -coupling);
    entries.emplace_back(row, b, coupling);
    entries.emplace_back(b, row, coupling);
    entries.emplace_back(row, row, idle[e] ? -1.0 : -1e-3);
  }
  return entries;
}

Eigen::VectorXd denseSolve(const std::vector<Eigen::Triplet<double>>& entries, int size,
                           const Eigen::VectorXd& rhs) {
  Eigen::SparseMatrix<double> sparse(size, size);
  sparse.setFromTriplets(entries.begin(), entries.end());
  return Eigen::MatrixXd(sparse).partialPivLu().solve(rhs);
}

TEST(PatternCachedLdlt, LeavesStoredZerosOutOfTheFactor) {
  constexpr int kVertices = 40;
  constexpr int kSize = 2 * kVertices;
  // Every third edge slack: the ring falls apart into chains, whose factor has no fill.
  std::vector<bool> idle(kVertices, false);
  for (int e = 0; e < kVertices; e += 3) idle[e] = true;
  const std::vector<Eigen::Triplet<double>> entries = ringSystem(kVertices, idle);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(kSize, -1.0, 2.0);

  PatternCachedLdlt with_zeros;
  PatternCachedLdlt without_zeros;
  without_zeros.leaveOutZeros();
  ASSERT_TRUE(with_zeros.factorize(entries, kSize));
  ASSERT_TRUE(without_zeros.factorize(entries, kSize));
  const Eigen::VectorXd expected = denseSolve(entries, kSize, rhs);
  EXPECT_LT((with_zeros.solve(rhs) - expected).norm(), 1e-12 * expected.norm());
  EXPECT_LT((without_zeros.solve(rhs) - expected).norm(), 1e-12 * expected.norm());
  // The idle rows and the couplings of the ring they cut add fill only with the zeros.
  EXPECT_LT(without_zeros.factorNonZeros(), with_zeros.factorNonZeros());
  EXPECT_EQ(without_zeros.zeroFreeAnalyses(), 1);
}

TEST(PatternCachedLdlt, AnalysesTheNonzerosAnewOnlyWhenTheyOutgrowThem) {
  constexpr int kVertices = 40;
  constexpr int kSize = 2 * kVertices;
  std::vector<bool> idle(kVertices, false);
  for (int e = 0; e < kVertices; e += 3) idle[e] = true;
  PatternCachedLdlt ldlt;
  ldlt.leaveOutZeros();
  ASSERT_TRUE(ldlt.factorize(ringSystem(kVertices, idle), kSize));
  ASSERT_EQ(ldlt.zeroFreeAnalyses(), 1);
  ASSERT_EQ(ldlt.analyses(), 1);

  // One more slack edge: its zeros fall within the analysed nonzeros (one edge of 40 is within
  // kMostZeroShare), which are kept.
  std::vector<bool> fewer = idle;
  fewer[1] = true;
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(kSize, 1.0, -3.0);
  ASSERT_TRUE(ldlt.factorize(ringSystem(kVertices, fewer), kSize));
  EXPECT_EQ(ldlt.zeroFreeAnalyses(), 1);
  Eigen::VectorXd expected = denseSolve(ringSystem(kVertices, fewer), kSize, rhs);
  EXPECT_LT((ldlt.solve(rhs) - expected).norm(), 1e-12 * expected.norm());

  // A slack edge taut again: a nonzero outside the analysed ones, analysed anew; the listed
  // pattern is the same, so the ordering and the slots are kept.
  std::vector<bool> more = idle;
  more[0] = false;
  ASSERT_TRUE(ldlt.factorize(ringSystem(kVertices, more), kSize));
  EXPECT_EQ(ldlt.zeroFreeAnalyses(), 2);
  EXPECT_EQ(ldlt.analyses(), 1);
  expected = denseSolve(ringSystem(kVertices, more), kSize, rhs);
  EXPECT_LT((ldlt.solve(rhs) - expected).norm(), 1e-12 * expected.norm());
}

TEST(PatternCachedLdlt, EntriesAddedDirectlyFactorizeAsListedOnes) {
  constexpr int kVertices = 30;
  constexpr int kSize = 2 * kVertices;
  std::vector<bool> idle(kVertices, false);
  PatternCachedLdlt factorization;
  factorization.leaveOutZeros();
  EXPECT_FALSE(factorization.beginDirect(kSize));  // nothing analysed yet
  ASSERT_TRUE(factorization.factorize(ringSystem(kVertices, idle), kSize));
  // Another taut set lists the same sequence: added directly, no new analysis.
  idle[4] = true;
  idle[17] = true;
  const std::vector<Eigen::Triplet<double>> entries = ringSystem(kVertices, idle);
  ASSERT_TRUE(factorization.beginDirect(kSize));
  for (const Eigen::Triplet<double>& t : entries) {
    ASSERT_TRUE(factorization.addDirect(t.row(), t.col(), t.value()));
  }
  ASSERT_TRUE(factorization.endDirect());
  ASSERT_TRUE(factorization.factorizeDirect());
  EXPECT_EQ(factorization.analyses(), 1);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(kSize, -1.0, 2.0);
  const Eigen::VectorXd expected = denseSolve(entries, kSize, rhs);
  EXPECT_LT((factorization.solve(rhs) - expected).norm(), 1e-12 * expected.norm());
  // A sequence that departs from the last one is refused, as is one cut short.
  ASSERT_TRUE(factorization.beginDirect(kSize));
  EXPECT_FALSE(factorization.addDirect(entries[1].row(), entries[1].col(), 1.0));
  ASSERT_TRUE(factorization.beginDirect(kSize));
  EXPECT_TRUE(factorization.addDirect(entries[0].row(), entries[0].col(), entries[0].value()));
  EXPECT_FALSE(factorization.endDirect());
  EXPECT_FALSE(factorization.beginDirect(kSize + 1));  // another size
}

TEST(PatternCachedLdlt, KeptAnalysesAreTakenUpAgainAndEachSolvesItsOwnSystem) {
  constexpr int kVertices = 30;
  constexpr int kSize = 2 * kVertices;
  std::vector<bool> idle(kVertices, false);
  idle[3] = true;
  // Two systems of the same size and entry count but other patterns, as a Newton step's
  // pivoting passes alternate; both leave stored zeros out.
  const std::vector<Eigen::Triplet<double>> first = ringSystem(kVertices, idle);
  const std::vector<Eigen::Triplet<double>> second = ringSystem(kVertices, idle, 2);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(kSize, -1.0, 2.0);
  const Eigen::VectorXd first_solution = denseSolve(first, kSize, rhs);
  const Eigen::VectorXd second_solution = denseSolve(second, kSize, rhs);
  PatternCachedLdlt one;  // keeps its last analysis only
  PatternCachedLdlt two;
  two.keepAnalyses(2);
  for (PatternCachedLdlt* factorization : {&one, &two}) {
    factorization->leaveOutZeros();
    for (int pass = 0; pass < 3; ++pass) {
      ASSERT_TRUE(factorization->factorize(first, kSize));
      EXPECT_LT((factorization->solve(rhs) - first_solution).norm(), 1e-12 * first_solution.norm());
      ASSERT_TRUE(factorization->factorize(second, kSize));
      EXPECT_LT((factorization->solve(rhs) - second_solution).norm(),
                1e-12 * second_solution.norm());
    }
  }
  EXPECT_EQ(one.analyses(), 6);
  EXPECT_EQ(two.analyses(), 2);
}

/// An edge Gram matrix listed with every entry it may use: `n` rows in a ring, each coupled to
/// the next by -0.3 where both are in use (`in_use`; 0 where either is idle) and to the one
/// `n / 2` away by 0.1; the coupling of rows 1 and 2 is 0 even while both are in use (a warp and
/// a weft edge at right angles). Idle rows keep their diagonal.
std::vector<Eigen::Triplet<double>> ringGram(int n, const std::vector<std::uint8_t>& in_use) {
  std::vector<Eigen::Triplet<double>> entries;
  const auto couple = [&](int a, int b, double value) {
    const double coupling = in_use[a] && in_use[b] ? value : 0.0;
    entries.emplace_back(a, b, coupling);
    entries.emplace_back(b, a, coupling);
  };
  for (int e = 0; e < n; ++e) {
    entries.emplace_back(e, e, 1.0 + 0.01 * e);
    couple(e, (e + 1) % n, e == 1 ? 0.0 : -0.3);
    if (e < n / 2) couple(e, e + n / 2, 0.1);
  }
  return entries;
}

/// Factorizes `entries` straight into the analysed pattern where it may, else as a list.
bool factorizeGram(PatternCachedLdlt& ldlt, const std::vector<Eigen::Triplet<double>>& entries,
                   int size) {
  if (!ldlt.beginDirect(size)) return ldlt.factorize(entries, size);
  for (const Eigen::Triplet<double>& t : entries) {
    if (!ldlt.addDirect(t.row(), t.col(), t.value())) return false;
  }
  return ldlt.endDirect() && ldlt.factorizeDirect();
}

TEST(PatternCachedLdlt, IdleRowsLeaveTheirEntriesOutWhileTheListedPatternHolds) {
  constexpr int kRows = 40;
  // Every fifth row idle, then every seventh from row 2.
  std::vector<std::uint8_t> first(kRows, 1);
  std::vector<std::uint8_t> second(kRows, 1);
  for (int e = 0; e < kRows; e += 5) first[e] = 0;
  for (int e = 2; e < kRows; e += 7) second[e] = 0;
  std::vector<std::uint8_t> in_use = first;
  PatternCachedLdlt ldlt;
  ldlt.leaveOutIdleRows(&in_use);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(kRows, -1.0, 2.0);
  ASSERT_TRUE(factorizeGram(ldlt, ringGram(kRows, in_use), kRows));
  // The idle rows' entries are left out and the zero coupling of rows 1 and 2 is kept: the
  // factor is that of the rows in use listed alone, with a nonzero there.
  std::vector<Eigen::Triplet<double>> used_alone;
  for (const Eigen::Triplet<double>& t : ringGram(kRows, in_use)) {
    if (t.row() != t.col() && !(in_use[t.row()] && in_use[t.col()])) continue;
    const bool zero_pair = t.row() + t.col() == 3 && t.row() * t.col() == 2;
    used_alone.emplace_back(t.row(), t.col(), zero_pair ? -0.3 : t.value());
  }
  PatternCachedLdlt alone;
  ASSERT_TRUE(alone.factorize(used_alone, kRows));
  EXPECT_EQ(ldlt.factorNonZeros(), alone.factorNonZeros());

  // Two sets of rows in use, alternating: each solves its own system, with the one listed
  // analysis (their fill differs by less than the growth that orders anew). The second's rows
  // that the first leaves idle grow the analysed entries once; then both fit them.
  for (int pass = 0; pass < 4; ++pass) {
    for (const std::vector<std::uint8_t>* set : {&first, &second}) {
      in_use = *set;
      const std::vector<Eigen::Triplet<double>> entries = ringGram(kRows, in_use);
      ASSERT_TRUE(factorizeGram(ldlt, entries, kRows));
      const Eigen::VectorXd expected = denseSolve(entries, kRows, rhs);
      EXPECT_LT((ldlt.solve(rhs) - expected).norm(), 1e-12 * expected.norm());
    }
  }
  EXPECT_EQ(ldlt.analyses(), 1);
  EXPECT_EQ(ldlt.zeroFreeAnalyses(), 2);
}

TEST(PatternCachedLdlt, IdleRowsThatSettleGetAnOrderingOfTheirOwn) {
  constexpr int kRows = 40;
  std::vector<std::uint8_t> in_use(kRows, 1);
  PatternCachedLdlt ldlt;
  ldlt.leaveOutIdleRows(&in_use);
  ASSERT_TRUE(factorizeGram(ldlt, ringGram(kRows, in_use), kRows));
  ASSERT_EQ(ldlt.analyses(), 1);
  // Every fourth row idle from now on: the ring falls apart into chains, first in the ring's
  // ordering; once they have settled they are ordered anew (one more listed analysis), and the
  // solutions stay those of their system throughout.
  for (int e = 0; e < kRows; e += 4) in_use[e] = 0;
  const std::vector<Eigen::Triplet<double>> entries = ringGram(kRows, in_use);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(kRows, 3.0, -1.0);
  const Eigen::VectorXd expected = denseSolve(entries, kRows, rhs);
  for (int k = 0; k < 40; ++k) {
    ASSERT_TRUE(factorizeGram(ldlt, entries, kRows));
    EXPECT_LT((ldlt.solve(rhs) - expected).norm(), 1e-12 * expected.norm());
  }
  EXPECT_EQ(ldlt.analyses(), 2);
}

}  // namespace
}  // namespace yarn_tearing::test
