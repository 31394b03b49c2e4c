#pragma once

#include <vector>

namespace yarn_tearing {

/// One point of a stress–strain curve.
struct CurvePoint {
  double strain = 0.0;  ///< engineering strain [-]
  double stress = 0.0;  ///< engineering stress [Pa]
};

/// Monotonic piecewise-linear stress–strain curve of a yarn material (paper §3.1, Figure 1).
///
/// Point 0 is the origin, the slope of the first segment is Young's modulus, point 1 is the yield
/// point and the last point is the breaking point. Beyond the last point the curve is extended with
/// the slope of its last segment. Elastic unloading follows Young's modulus, so the plastic strain
/// that a stress leaves behind is strainAtStress(stress) - stress / E.
class StressStrainCurve {
 public:
  /// Throws std::invalid_argument naming the problem unless: at least 3 points, the first is (0,
  /// 0), strains and stresses strictly increasing, all finite.
  explicit StressStrainCurve(std::vector<CurvePoint> points);

  const std::vector<CurvePoint>& points() const { return points_; }
  /// Young's modulus [Pa]: slope of the first segment.
  double youngsModulus() const { return youngs_modulus_; }
  /// Strain at the yield point [-].
  double yieldStrain() const { return points_[1].strain; }
  /// Stress at the yield point [Pa].
  double yieldStress() const { return points_[1].stress; }
  /// Strain at the breaking point [-].
  double breakingStrain() const { return points_.back().strain; }
  /// Stress at the breaking point [Pa] (the tenacity times the density).
  double breakingStress() const { return points_.back().stress; }

  /// Strain on the loading curve at a stress [Pa] -> [-]; linear (slope E) for stress <= 0.
  double strainAtStress(double stress) const;
  /// Stress on the loading curve at a strain [-] -> [Pa]; linear (slope E) for strain <= 0.
  double stressAtStrain(double strain) const;
  /// Plastic strain [-] left after loading to `stress` [Pa] and unloading elastically (>= 0).
  double plasticStrainAtStress(double stress) const;

 private:
  std::vector<CurvePoint> points_;
  double youngs_modulus_ = 0.0;
};

}  // namespace yarn_tearing
