#include "yarn_tearing/core/material/stress_strain_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace yarn_tearing {
namespace {

std::string describe(const CurvePoint& p) {
  return "(" + std::to_string(p.strain) + ", " + std::to_string(p.stress) + ")";
}

// Linear interpolation of y(x) over a monotonic table, extended with the end slopes.
template <typename X, typename Y>
double interpolate(const std::vector<CurvePoint>& pts, double x, X get_x, Y get_y) {
  std::size_t upper = 1;
  while (upper + 1 < pts.size() && get_x(pts[upper]) < x) ++upper;
  const CurvePoint& p0 = pts[upper - 1];
  const CurvePoint& p1 = pts[upper];
  const double t = (x - get_x(p0)) / (get_x(p1) - get_x(p0));
  return get_y(p0) + t * (get_y(p1) - get_y(p0));
}

}  // namespace

StressStrainCurve::StressStrainCurve(std::vector<CurvePoint> points) : points_(std::move(points)) {
  if (points_.size() < 3) {
    throw std::invalid_argument(
        "stress_strain needs at least 3 points (origin, yield, break), got " +
        std::to_string(points_.size()));
  }
  for (const CurvePoint& p : points_) {
    if (!std::isfinite(p.strain) || !std::isfinite(p.stress)) {
      throw std::invalid_argument("stress_strain point " + describe(p) + " is not finite");
    }
  }
  if (points_[0].strain != 0.0 || points_[0].stress != 0.0) {
    throw std::invalid_argument("stress_strain must start at (0, 0), got " + describe(points_[0]));
  }
  for (std::size_t i = 1; i < points_.size(); ++i) {
    if (!(points_[i].strain > points_[i - 1].strain) ||
        !(points_[i].stress > points_[i - 1].stress)) {
      throw std::invalid_argument(
          "stress_strain must be strictly increasing in strain and stress: " +
          describe(points_[i - 1]) + " then " + describe(points_[i]));
    }
  }
  youngs_modulus_ = points_[1].stress / points_[1].strain;
}

double StressStrainCurve::strainAtStress(double stress) const {
  if (stress <= 0.0) return stress / youngs_modulus_;
  return interpolate(
      points_, stress, [](const CurvePoint& p) { return p.stress; },
      [](const CurvePoint& p) { return p.strain; });
}

double StressStrainCurve::stressAtStrain(double strain) const {
  if (strain <= 0.0) return strain * youngs_modulus_;
  return interpolate(
      points_, strain, [](const CurvePoint& p) { return p.strain; },
      [](const CurvePoint& p) { return p.stress; });
}

double StressStrainCurve::plasticStrainAtStress(double stress) const {
  if (stress <= yieldStress()) return 0.0;
  return std::max(0.0, strainAtStress(stress) - stress / youngs_modulus_);
}

}  // namespace yarn_tearing
