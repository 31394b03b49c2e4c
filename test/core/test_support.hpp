#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing::test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kGravity = 9.81;  ///< [m/s^2]

/// A time step [s] in a parameterised test's name: "dt1em4" for 1e-4, "dt2em3" for 2e-3
/// (tools/test_core.sh leaves the dt1em4 cases out of the sanitizer run; Release runs them).
inline std::string stepName(double dt) {
  const long exponent = std::lround(std::floor(std::log10(dt) + 1e-9));
  const long mantissa = std::lround(dt / std::pow(10.0, static_cast<double>(exponent)));
  return "dt" + std::to_string(mantissa) + "em" + std::to_string(-exponent);
}

/// An angle [rad] in a parameterised test's name: "180deg" for pi.
inline std::string angleName(double radians) {
  return std::to_string(std::lround(radians * 180.0 / kPi)) + "deg";
}

/// A fibre of density 1520 kg/m^3 with the given stress-strain points.
inline Material fibre(const char* name, std::vector<CurvePoint> points) {
  Material m;
  m.name = name;
  m.density = 1520.0;
  m.curve = StressStrainCurve(std::move(points));
  return m;
}

/// Cotton-like fibre: E = 7.6 GPa, yield at 1.5 % / 114 MPa, break at 7.1 % / 486 MPa.
inline Material cottonLike() {
  return fibre("cotton_like", {{0.0, 0.0}, {0.015, 1.14e8}, {0.071, 4.86e8}});
}

/// A weaker fibre (lower modulus and breaking point), as the left yarn of the paper's Figure 4.
inline Material weakLike() {
  return fibre("weak_like", {{0.0, 0.0}, {0.01, 4.0e7}, {0.05, 1.6e8}});
}

/// The radius of hangingYarn()'s yarn [m] and its cross-section [m^2].
constexpr double kYarnRadius = 1.0e-4;
constexpr double kYarnArea = kPi * kYarnRadius * kYarnRadius;

/// 0.3 m, 25 vertices, r = 0.1 mm, hanging along -z from the origin, vertex 0 pinned.
inline YarnSpec hangingYarn(const Material& material = cottonLike()) {
  YarnSpec spec;
  spec.name = "yarn";
  spec.material = material;
  spec.radius = kYarnRadius;
  spec.length = 0.3;
  spec.num_vertices = 25;
  spec.pinned = {0};
  return spec;
}

/// hangingYarn() with `num_vertices` [-] 12.5 mm apart along +x, vertex 0 pinned, its edge
/// `weak` at `factor` [-] of the yarn's strength, and the yarn stretched to 0.99 of that edge's
/// breaking strain (in its elastic range for a factor of a fifth).
inline Scene weakEdgeYarnScene(int num_vertices, std::uint32_t weak, double factor) {
  YarnSpec spec = hangingYarn();
  spec.num_vertices = num_vertices;
  spec.length = 0.0125 * (num_vertices - 1);
  spec.direction = Eigen::Vector3d::UnitX();
  Scene scene = buildScene({spec});
  scene.edges.strength_factor[weak] = factor;
  const StressStrainCurve& curve = spec.material.curve;
  const double breaking_strain = curve.strainAtStress(factor * curve.breakingStress());
  for (Eigen::Vector3d& x : scene.vertices.position) x *= 1.0 + 0.99 * breaking_strain;
  return scene;
}

inline SimulationParameters parametersWithoutGravity(double dt = 1.0e-3) {
  SimulationParameters p;
  p.time_step = dt;
  p.gravity.setZero();
  return p;
}

/// Kinetic energy of the free vertices [J].
inline double kineticEnergy(const Simulator& sim) {
  const VertexSet& v = sim.scene().vertices;
  double energy = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v.isSupport(i)) energy += 0.5 * v.mass[i] * v.velocity[i].squaredNorm();
  }
  return energy;
}

/// Sum of the intact edge lengths of yarn 0 [m].
inline double yarnLength(const Simulator& sim) {
  const Scene& s = sim.scene();
  double length = 0.0;
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    if (!s.edges.intact(e)) continue;
    length += (s.vertices.position[s.edges.vertex_b[e]] - s.vertices.position[s.edges.vertex_a[e]])
                  .norm();
  }
  return length;
}

inline bool allFinite(const Simulator& sim) {
  for (const auto& x : sim.scene().vertices.position) {
    if (!x.allFinite()) return false;
  }
  for (const auto& v : sim.scene().vertices.velocity) {
    if (!v.allFinite()) return false;
  }
  for (double t : sim.scene().edges.tension) {
    if (!std::isfinite(t)) return false;
  }
  return true;
}

inline Eigen::Vector3d momentum(const Simulator& sim) {
  const VertexSet& v = sim.scene().vertices;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < v.size(); ++i) p += v.mass[i] * v.velocity[i];
  return p;
}

}  // namespace yarn_tearing::test
