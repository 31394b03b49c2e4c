#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "yarn_tearing/core/material/material.hpp"

namespace yarn_tearing {

/// Random scatter of each edge's strength (breaking stress), so that a uniform yarn breaks at one
/// place and a long yarn is weaker than a short one (weakest link). The statistics describe
/// specimens of `gauge_length`: a yarn of that length has mean strength sigma_b (the curve's last
/// point) and the given CV, whatever its vertex count.
struct StrengthScatter {
  /// Weibull modulus m [-] of the strength; 0 = no scatter. Typical yarns: 5..20.
  double weibull_modulus = 0.0;
  /// Instead of the modulus: the coefficient of variation of the strength [-] of specimens of
  /// gauge_length (standard deviation over mean, as yarn strength is usually reported; 0.05..0.15
  /// for most yarns), in (0, 1]; the Weibull modulus with that CV is used. 0 = use
  /// weibull_modulus. Not both.
  double coefficient_of_variation = 0.0;
  /// Gauge length [m] at which the material's curve (its breaking stress sigma_b) is the mean and
  /// the scatter is the one given; 0.5 m is the usual single-end yarn test length (ISO 2062).
  double gauge_length = 0.5;
  /// Seed of the deterministic generator; the same seed gives the same factors on any platform.
  unsigned long long seed = 1;
};

/// Everything needed to build one straight yarn.
struct YarnSpec {
  std::string name;   ///< unique name
  Material material;  ///< fibre material
  /// Yarn radius r [m]. The load-bearing area is pi r^2 (paper §3.2) unless `tex` > 0.
  double radius = 1.0e-4;
  /// Linear density [tex = g/km]; > 0 sizes the yarn by mass instead of by radius: the
  /// load-bearing (fibre) area is tex*1e-6/density and the radius is sqrt(area/(pi*packing)).
  double tex = 0.0;
  double packing_fraction = 0.6;                    ///< fibre volume fraction of the yarn [-]
  double length = 0.3;                              ///< total length [m]
  int num_vertices = 25;                            ///< N >= 2 vertices, N - 1 edges
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  ///< first vertex [m]
  Eigen::Vector3d direction = Eigen::Vector3d(0.0, 0.0, -1.0);  ///< unit-less, normalized
  std::vector<int> pinned;           ///< pinned vertices; negative counts from end
  double end_mass = 0.0;             ///< extra point mass on the last vertex [kg]
  StrengthScatter strength_scatter;  ///< optional strength scatter

  /// Throws std::invalid_argument naming the field and what is allowed.
  void validate() const;
  /// Load-bearing cross-section area [m^2].
  double area() const;
  /// Mass per unit length [kg/m].
  double linearDensity() const;
  /// Radius used for drawing and reporting [m].
  double effectiveRadius() const;
};

}  // namespace yarn_tearing
