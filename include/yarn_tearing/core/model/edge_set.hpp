#pragma once

#include <cstdint>
#include <vector>

namespace yarn_tearing {

/// All edges (yarn segments) of a scene, structure-of-arrays; index = global edge id.
struct EdgeSet {
  std::vector<std::uint32_t> vertex_a;       ///< first vertex (global id)
  std::vector<std::uint32_t> vertex_b;       ///< second vertex (global id)
  std::vector<std::uint32_t> yarn;           ///< index of the owning yarn (or fabric family group)
  std::vector<double> original_rest_length;  ///< L0 [m]
  std::vector<double> rest_length;           ///< plastic rest length L0 (1 + eps_p) [m]
  std::vector<double> area;                  ///< load-bearing cross-section [m^2]
  /// Strength factor f [-]: the edge tears at the stress f * sigma_b (scatter; 1 = none).
  std::vector<double> strength_factor;
  /// Strain at which the edge tears [-]: its curve's strain at f * sigma_b, relative to L0. Set by
  /// assignBreakingStrains (buildScene and the Simulator's constructors call it).
  std::vector<double> breaking_strain;
  std::vector<double> strain_limit;    ///< elastic strain / (1 + eps_p): the edge is held to |x_a -
                                       ///< x_b| <= rest_length (1 + s) [-]
  std::vector<double> plastic_strain;  ///< eps_p, relative to L0 [-]
  std::vector<double> tension;         ///< axial force, constraint + spring [N]
  std::vector<double> spring_tension;  ///< soft-spring part of the tension [N]
  std::vector<double> stress;          ///< tension / area [Pa]
  std::vector<double> strain;          ///< eps_p + elastic strain, relative to L0 [-]
  std::vector<double> strain_rate;     ///< d(strain)/dt [1/s]
  /// Time the edge has been under tension without a break [s] (0 while slack).
  std::vector<double> loading_time;
  std::vector<double> loading_start_strain;  ///< strain when that loading began [-]
  /// Factor f [-] on the material curve's stresses at the edge's loading rate
  /// (RateDependence); 1 for a rate-independent material.
  std::vector<double> rate_factor;
  std::vector<std::uint8_t> broken;  ///< 1 once torn

  std::size_t size() const { return vertex_a.size(); }
  bool intact(std::size_t e) const { return broken[e] == 0; }
  /// Appends an unloaded intact edge.
  void add(std::uint32_t a, std::uint32_t b, std::uint32_t yarn_index, double rest, double area,
           double strength);
};

}  // namespace yarn_tearing
