#pragma once

namespace yarn_tearing {

/// Rate dependence of a material's stress-strain curve. The curve a material gives is the one
/// measured at the single-end tensile test's rate, 100 % of the gauge length per minute. At a
/// strain rate eps_dot the curve's stresses (and so Young's modulus and the breaking stress) are
/// multiplied by
///   f(eps_dot) = 1 + k log10(clamp(eps_dot, kMinStrainRate, kMaxStrainRate) /
///   kReferenceStrainRate)
/// at unchanged strains, k the material's rate sensitivity: the breaking stress rises linearly with
/// the logarithm of the rate, as textile fibres and yarns show (Meredith 1954), over the range of
/// rates those measurements cover, and stays at its end values outside it, so it is bounded.
struct RateDependence {
  /// Strain rate of the reference curve [1/s]: 100 % of the gauge length per minute.
  static constexpr double kReferenceStrainRate = 1.0 / 60.0;
  /// Slowest strain rate the law follows [1/s] (0.001 %/s, Meredith's slowest); slower is as this.
  static constexpr double kMinStrainRate = 1.0e-5;
  /// Fastest strain rate the law follows [1/s] (1000 %/s, Meredith's fastest); faster is as this.
  static constexpr double kMaxStrainRate = 10.0;
  /// Largest rate sensitivity accepted [-]: keeps f at the slowest rate above 0.19.
  static constexpr double kMaxSensitivity = 0.25;

  /// Stress factor f [-] at `strain_rate` [1/s] (any value; <= kMinStrainRate counts as that) for
  /// rate sensitivity `sensitivity` k [-] (fractional rise of the stresses per decade of rate).
  /// Exactly 1 when k = 0.
  static double stressFactor(double sensitivity, double strain_rate);
};

}  // namespace yarn_tearing
