#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_support.hpp"
#include "yarn_tearing/core/model/fabric_spec.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing::test {

/// A cotton-like plain-weave patch hanging along -z from its first row (at the origin), the weft
/// along +x: `ends` x `picks` vertices, 0.1 mm yarns, no crimp, no scatter.
inline FabricSpec cottonPatch(int ends, int picks, double weft_length, double warp_length) {
  FabricSpec spec;
  spec.name = "cloth";
  spec.ends = ends;
  spec.picks = picks;
  spec.weft_length = weft_length;
  spec.warp_length = warp_length;
  spec.warp = hangingYarn();
  spec.weft = hangingYarn();
  spec.pinned_sides = {FabricSide::kFirstRow};
  return spec;
}

/// A side x side cotton weave, 12.5 mm between yarns, pinned at its two top corners.
inline Simulator heldAtCorners(int side, const SimulationParameters& parameters) {
  const double length = 0.0125 * (side - 1);
  FabricSpec spec = cottonPatch(side, side, length, length);
  spec.pinned_sides.clear();
  spec.pinned = {{0, 0}, {0, -1}};
  return Simulator(parameters, {}, {spec});
}

/// Two side x side weaves held at their two top corners, air damping 0.05, at steps of
/// `time_step` [s]: `usual` with the default solvers, `switched` with the solver switch `compare`
/// (a SimulationParameters::force_* flag) set, for two ways of solving the same steps.
struct HeldBothWays {
  Simulator usual;
  Simulator switched;
};
inline HeldBothWays heldAtCornersBothWays(int side, bool SimulationParameters::*compare,
                                          double time_step = SimulationParameters{}.time_step) {
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  parameters.time_step = time_step;
  SimulationParameters switched = parameters;
  switched.*compare = true;
  return {heldAtCorners(side, parameters), heldAtCorners(side, switched)};
}

/// Spacing [m] between the yarns of settledPatch().
constexpr double kPatchSpacing = 0.0125;

/// The 16 x 12 cotton patch (kPatchSpacing between yarns) hanging from its first row, air
/// damping 0.05, settled 0.2 s at steps of `time_step` [s].
inline Simulator settledPatch(double time_step = SimulationParameters{}.time_step) {
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  parameters.time_step = time_step;
  Simulator sim(parameters, {}, {cottonPatch(16, 12, 15 * kPatchSpacing, 11 * kPatchSpacing)});
  while (sim.time() < 0.2) sim.step();
  return sim;
}

/// The middle of the scene's first fabric, between its first and last vertex [m]: the middle of a
/// cell when both counts of yarns are even.
inline Eigen::Vector3d patchMiddle(const Scene& scene) {
  return 0.5 * (scene.vertices.position[scene.fabricVertex(0, 0, 0)] +
                scene.vertices.position[scene.fabricVertex(0, -1, -1)]);
}

/// A ball named "ball" of `radius` [m] at `center` [m].
inline Obstacle ball(const Eigen::Vector3d& center, double radius) {
  Obstacle o;
  o.name = "ball";
  o.shape = ObstacleShape::kSphere;
  o.radius = radius;
  o.pose.translation() = center;
  return o;
}

/// Global vertex ids of the scene's first fabric's last row (a strip's grips).
inline std::vector<std::uint32_t> lastRow(const Scene& scene) {
  const Fabric& fabric = scene.fabrics[0];
  std::vector<std::uint32_t> row;
  for (std::uint32_t c = 0; c < fabric.ends; ++c) row.push_back(fabric.vertex(fabric.picks - 1, c));
  return row;
}

/// Positions of the given vertices [m].
inline std::vector<Eigen::Vector3d> positionsOf(const Scene& scene,
                                                const std::vector<std::uint32_t>& vertices) {
  std::vector<Eigen::Vector3d> positions;
  for (std::uint32_t v : vertices) positions.push_back(scene.vertices.position[v]);
  return positions;
}

/// The breaking force sigma_b pi r^2 of a fabric family's yarn [N].
inline double breakingForce(const YarnSpec& yarn) {
  return yarn.material.curve.breakingStress() * yarn.area();
}

/// Steps `a` and `b` `steps` times side by side, each step converged, and expects them to end in
/// the same state: positions within `position_tolerance` [m], tensions within
/// `tension_tolerance` of the largest [-] (two ways of solving the same step).
inline void expectSameSteps(Simulator& a, Simulator& b, int steps, double position_tolerance,
                            double tension_tolerance) {
  for (int k = 0; k < steps; ++k) {
    a.step();
    b.step();
    ASSERT_TRUE(a.lastHealth().projection_converged) << "step " << k;
    ASSERT_TRUE(b.lastHealth().projection_converged) << "step " << k;
  }
  const Scene& sa = a.scene();
  const Scene& sb = b.scene();
  double position_difference = 0.0;
  for (std::size_t v = 0; v < sa.vertices.size(); ++v) {
    position_difference =
        std::max(position_difference, (sa.vertices.position[v] - sb.vertices.position[v]).norm());
  }
  double tension_difference = 0.0;
  double largest_tension = 0.0;
  for (std::size_t e = 0; e < sa.edges.size(); ++e) {
    tension_difference =
        std::max(tension_difference, std::abs(sa.edges.tension[e] - sb.edges.tension[e]));
    largest_tension = std::max(largest_tension, std::abs(sb.edges.tension[e]));
  }
  EXPECT_LT(position_difference, position_tolerance);
  ASSERT_GT(largest_tension, 0.0);
  EXPECT_LT(tension_difference, tension_tolerance * largest_tension);
}

}  // namespace yarn_tearing::test
