#include "yarn_tearing/core/linalg/banded_ldlt.hpp"

#include <algorithm>
#include <cmath>

namespace yarn_tearing {

bool BandedLdlt::factorize(const std::vector<Eigen::Triplet<double>>& entries, int n) {
  int bandwidth = 0;
  for (const Eigen::Triplet<double>& t : entries) {
    if (t.row() >= t.col()) bandwidth = std::max(bandwidth, t.row() - t.col());
  }
  begin(n, bandwidth);
  for (const Eigen::Triplet<double>& t : entries) add(t.row(), t.col(), t.value());
  return factorize();
}

void BandedLdlt::begin(int n, int half_bandwidth) {
  size_ = n;
  bandwidth_ = half_bandwidth;
  matrix_.assign(static_cast<std::size_t>(n) * (half_bandwidth + 1), 0.0);
}

bool BandedLdlt::factorize() {
  const int n = size_;
  const int b = bandwidth_;
  const int stride = b + 1;
  factor_ = matrix_;
  // Column by column (right-looking): L_ij = A_ij / d_j, then the trailing triangle of the band
  // loses l d l^T; its updates are independent, so the elimination is bound by throughput rather
  // than by the latency of one long chain of products.
  double* f = factor_.data();
  for (int j = 0; j < n; ++j) {
    double* column = f + static_cast<std::size_t>(j) * stride;
    const double d = column[0];
    if (!(d != 0.0) || !std::isfinite(d)) return false;
    const int below = std::min(b, n - 1 - j);
    for (int r = 1; r <= below; ++r) {
      const double w = column[r];  // L_(j+r) j d_j
      if (w == 0.0) continue;
      const double l = w / d;
      double* target = f + static_cast<std::size_t>(j + r) * stride;  // column j + r
      for (int i = r; i <= below; ++i) target[i - r] -= column[i] * l;
    }
    for (int r = 1; r <= below; ++r) column[r] /= d;
  }
  return true;
}

void BandedLdlt::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& result) const {
  const int n = size_;
  const int b = bandwidth_;
  const int stride = b + 1;
  const double* f = factor_.data();
  result = rhs;
  double* x = result.data();
  for (int j = 0; j < n; ++j) {
    const double* column = f + static_cast<std::size_t>(j) * stride;
    const double y = x[j];
    const int below = std::min(b, n - 1 - j);
    double* next = x + j;
    for (int r = 1; r <= below; ++r) next[r] -= column[r] * y;
  }
  for (int j = 0; j < n; ++j) x[j] /= f[static_cast<std::size_t>(j) * stride];
  for (int j = n - 1; j >= 0; --j) {
    const double* column = f + static_cast<std::size_t>(j) * stride;
    const double* next = x + j;
    const int below = std::min(b, n - 1 - j);
    // Two sums: the dot product's chain of additions halved.
    double even = 0.0;
    double odd = 0.0;
    int r = 1;
    for (; r + 1 <= below; r += 2) {
      even += column[r] * next[r];
      odd += column[r + 1] * next[r + 1];
    }
    if (r <= below) even += column[r] * next[r];
    x[j] -= even + odd;
  }
}

void BandedLdlt::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& result) const {
  const int n = size_;
  const int b = bandwidth_;
  const int stride = b + 1;
  result.setZero(n);
  for (int j = 0; j < n; ++j) {
    const double* column = matrix_.data() + static_cast<std::size_t>(j) * stride;
    result[j] += column[0] * x[j];
    const int below = std::min(b, n - 1 - j);
    for (int r = 1; r <= below; ++r) {
      result[j + r] += column[r] * x[j];
      result[j] += column[r] * x[j + r];
    }
  }
}

}  // namespace yarn_tearing
