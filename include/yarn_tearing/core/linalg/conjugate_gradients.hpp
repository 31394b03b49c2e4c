#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace yarn_tearing {

/// Preconditioned conjugate gradients for A x = b, A symmetric positive definite and given as a
/// product, with the updates and the stop of Eigen's ConjugateGradient, whose four work vectors
/// this keeps from one solve to the next: a solve of an unchanged size allocates nothing. Eigen's
/// allocates them in every solve, 4 q doubles; where the heap's top is given back to the system
/// when they are freed (glibc's start thresholds, 128 KiB), every solve faults their pages in
/// again, which doubled a hanging 64 x 64 fabric's step.
class ConjugateGradients {
 public:
  /// Solves A x = b from the guess in `x`: `multiply(v, out)` sets out = A v and
  /// `precondition(v, out)` sets out = P^-1 v (P the preconditioner, out of v's size). Stops
  /// once |b - A x| < `tolerance` |b| or after `max_iterations`; true when it got there.
  template <typename Multiply, typename Precondition>
  bool solve(const Multiply& multiply, const Precondition& precondition,
             const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::VectorXd& x, double tolerance,
             int max_iterations) {
    const Eigen::Index n = x.size();
    product_.resize(n);
    multiply(x, product_);
    residual_ = b - product_;
    const double rhs_norm2 = b.squaredNorm();
    if (rhs_norm2 == 0.0) {
      x.setZero();
      return true;
    }
    const double threshold =
        std::max(tolerance * tolerance * rhs_norm2, std::numeric_limits<double>::min());
    double residual_norm2 = residual_.squaredNorm();
    if (residual_norm2 < threshold) return std::sqrt(residual_norm2 / rhs_norm2) <= tolerance;
    direction_.resize(n);
    preconditioned_.resize(n);
    precondition(residual_, direction_);
    double r_dot_z = residual_.dot(direction_);
    for (int i = 0; i < max_iterations; ++i) {
      multiply(direction_, product_);
      const double alpha = r_dot_z / direction_.dot(product_);
      x += alpha * direction_;
      residual_ -= alpha * product_;
      residual_norm2 = residual_.squaredNorm();
      if (residual_norm2 < threshold) break;
      precondition(residual_, preconditioned_);
      const double last_r_dot_z = r_dot_z;
      r_dot_z = residual_.dot(preconditioned_);
      direction_ = preconditioned_ + (r_dot_z / last_r_dot_z) * direction_;
    }
    return std::sqrt(residual_norm2 / rhs_norm2) <= tolerance;
  }

 private:
  Eigen::VectorXd residual_;        ///< b - A x
  Eigen::VectorXd direction_;       ///< the search direction p
  Eigen::VectorXd preconditioned_;  ///< P^-1 (b - A x)
  Eigen::VectorXd product_;         ///< A x, then A p
};

}  // namespace yarn_tearing
