// Yarns held at both ends, as robots hold them: a taut span between two pins, two grippers drawing
// a yarn apart, a grasp pulled sideways between a pin and a loaded free end, a plucked span. The
// tension of a span between two holders moves no free vertex along the span, so the vertices' force
// balances alone cannot fix it; the estimate must still be the tension the span's stretch carries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <tuple>

#include "test_support.hpp"
#include "yarn_tearing/core/lab/stiff_reference_yarn.hpp"

namespace yarn_tearing::test {
namespace {

/// A straight yarn along +x from the origin, `num_vertices` vertices, 0.3 m long.
YarnSpec spanAlongX(int num_vertices) {
  YarnSpec spec = hangingYarn();
  spec.num_vertices = num_vertices;
  spec.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  spec.pinned.clear();
  return spec;
}

/// The scene of `spec` with every vertex moved along x so that each edge is stretched by
/// `pretension` [N] (elastic, below yield).
Scene stretchedScene(const YarnSpec& spec, double pretension) {
  Scene scene = buildScene({spec});
  const double strain = pretension / (spec.material.curve.youngsModulus() * spec.area());
  for (Eigen::Vector3d& x : scene.vertices.position) x *= 1.0 + strain;
  return scene;
}

/// The tension edge e's stretch implies, E A (l - L) / L0, tension-only [N].
double stretchTension(const Simulator& sim, std::size_t e) {
  const Scene& s = sim.scene();
  const double length =
      (s.vertices.position[s.edges.vertex_b[e]] - s.vertices.position[s.edges.vertex_a[e]]).norm();
  const double stiffness = s.yarns[s.edges.yarn[e]].material.curve.youngsModulus() *
                           s.edges.area[e] / s.edges.original_rest_length[e];
  return std::max(0.0, stiffness * (length - s.edges.rest_length[e]));
}

/// Plastic strain [-] the curve leaves after loading to a strain [-].
double plasticStrainAtStrain(const StressStrainCurve& curve, double strain) {
  return curve.plasticStrainAtStress(curve.stressAtStrain(strain));
}

SimulationParameters heldParameters(double dt, bool gravity) {
  SimulationParameters p = parametersWithoutGravity(dt);
  if (gravity) p.gravity = Eigen::Vector3d(0.0, 0.0, -kGravity);
  return p;
}

std::string spanCaseName(double dt, bool gravity) {
  return "dt " + std::to_string(dt) + (gravity ? ", gravity" : ", no gravity");
}

class HeldYarn : public ::testing::TestWithParam<std::tuple<double, bool>> {};

// A span pinned at both ends with a pretension: every edge's estimated tension is the tension its
// stretch implies, in every step; never negative; each support pulls inward with the pretension.
TEST_P(HeldYarn, PinnedSpanCarriesTheTensionOfItsStretch) {
  const auto [dt, gravity] = GetParam();
  const double pretension = 2.0;  // [N], 64 MPa: below the yield point
  YarnSpec spec = spanAlongX(25);
  spec.pinned = {0, -1};
  Simulator sim(heldParameters(dt, gravity), stretchedScene(spec, pretension));
  const std::uint32_t last = sim.scene().globalVertex(0, -1);
  double worst = 0.0;
  while (sim.time() < 0.3) {
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged);
    for (std::size_t e = 0; e < sim.scene().edges.size(); ++e) {
      const double estimate = sim.scene().edges.tension[e];
      const double geometric = stretchTension(sim, e);
      ASSERT_GE(estimate, 0.0) << spanCaseName(dt, gravity) << ", edge " << e << ", t "
                               << sim.time();
      worst = std::max(worst, std::abs(estimate - geometric) / geometric);
      ASSERT_NEAR(estimate, geometric, 0.02 * geometric)
          << spanCaseName(dt, gravity) << ", edge " << e << ", t " << sim.time();
    }
    ASSERT_NEAR(sim.supportForce(0).x(), pretension, 0.02 * pretension)
        << spanCaseName(dt, gravity);
    ASSERT_NEAR(sim.supportForce(last).x(), -pretension, 0.02 * pretension)
        << spanCaseName(dt, gravity);
  }
  std::cout << spanCaseName(dt, gravity) << ": largest relative error " << worst << "\n";
}

// A yarn pinned at one end, loaded at its free end through a 50 g weight by a force F along +x
// (with a dashpot, as a test machine's load train, so that it settles), and grasped in the middle
// by a gripper that is moved sideways by h: the near side (pin to gripper) is a straight span whose
// tension is E A (|g| - L/2) / (L/2), the far side carries F, and the gripper feels the sum of the
// two pulls (the triangle of forces).
TEST_P(HeldYarn, GraspPulledSidewaysBalancesATriangleOfForces) {
  const auto [dt, gravity] = GetParam();
  const double force = 3.0;  // [N] on the free end
  const double h = 0.018;    // [m] sideways offset of the gripper
  YarnSpec spec = spanAlongX(25);
  spec.pinned = {0};
  spec.end_mass = 0.05;         // [kg]
  const double dashpot = 20.0;  // [N s/m], about critical for the far side and the weight
  SimulationParameters p = heldParameters(dt, gravity);
  p.air_damping = 0.02;  // [N s/m^2] settles the spans' sideways swing (explicit: rate dt c/mu < 1)
  Simulator sim(p, {spec});
  const std::uint32_t middle = 12;
  const std::uint32_t end = sim.scene().globalVertex(0, -1);
  const Eigen::Vector3d grasp_start = sim.scene().vertices.position[middle];
  const double ramp = 0.2;  // [s]
  while (sim.time() < 2.0) {
    const Eigen::Vector3d end_velocity = sim.scene().vertices.velocity[end];
    sim.setAppliedForce(end, Eigen::Vector3d(force, 0.0, 0.0) - dashpot * end_velocity);
    const double s = std::min(1.0, (sim.time() + dt) / ramp);
    sim.setKinematicTarget(middle, grasp_start + Eigen::Vector3d(0.0, h * s * s * (3 - 2 * s), 0));
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged)
        << spanCaseName(dt, gravity) << ", t " << sim.time() << ", violation "
        << sim.lastHealth().max_constraint_violation << ", mismatch "
        << sim.lastHealth().force_mismatch << ", iterations "
        << sim.lastHealth().projection_iterations;
  }
  const Eigen::Vector3d g = sim.scene().vertices.position[middle];
  const double near_rest = 0.5 * spec.length;
  const double near_tension =
      spec.material.curve.youngsModulus() * kYarnArea * (g.norm() - near_rest) / near_rest;
  ASSERT_GT(near_tension, 1.0);  // the near side is taut and elastic (below 3.5 N at yield)
  const Scene& s = sim.scene();
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    const double expected = e < middle ? near_tension : force;
    EXPECT_NEAR(s.edges.tension[e], expected, 0.02 * expected)
        << spanCaseName(dt, gravity) << ", edge " << e;
  }
  // The far side with its weight hangs from the gripper: the gripper feels the near side's pull,
  // the load applied at the end and the far side's weight.
  Eigen::Vector3d far_weight = Eigen::Vector3d::Zero();
  for (std::uint32_t v = middle; v <= end; ++v) far_weight += s.vertices.mass[v] * p.gravity;
  const Eigen::Vector3d triangle =
      near_tension * (-g / g.norm()) + s.vertices.applied_force[end] + far_weight;
  EXPECT_LT((sim.supportForce(middle) - triangle).norm(), 0.02 * triangle.norm())
      << spanCaseName(dt, gravity) << ": gripper feels " << sim.supportForce(middle).transpose()
      << ", triangle " << triangle.transpose();
}

// An edge between two pins, which no projection can move: it carries the tension of its stretch,
// its holders feel it, and it tears when its holders are drawn to its breaking length.
TEST(HeldYarnEdge, EdgeBetweenTwoPinsCarriesItsStretchAndTears) {
  const double pretension = 2.0;  // [N]
  YarnSpec spec = spanAlongX(2);
  spec.pinned = {0, -1};
  Simulator sim(parametersWithoutGravity(), stretchedScene(spec, pretension));
  sim.step();
  EXPECT_NEAR(sim.scene().edges.tension[0], pretension, 1e-6 * pretension);
  EXPECT_NEAR(sim.supportForce(0).x(), pretension, 1e-6 * pretension);
  EXPECT_NEAR(sim.supportForce(1).x(), -pretension, 1e-6 * pretension);
  EXPECT_TRUE(sim.takeTearEvents().empty());
  // Pinned again past the breaking length: it tears in the next step.
  const double breaking_strain = spec.material.curve.breakingStrain();
  sim.setKinematicTarget(1, Eigen::Vector3d(spec.length * (1.0 + 1.01 * breaking_strain), 0, 0));
  sim.step();
  EXPECT_EQ(sim.takeTearEvents().size(), 1u);
}

INSTANTIATE_TEST_SUITE_P(StepsAndGravity, HeldYarn,
                         ::testing::Combine(::testing::Values(1.0e-3, 1.0e-4), ::testing::Bool()),
                         [](const ::testing::TestParamInfo<std::tuple<double, bool>>& info) {
                           return stepName(std::get<0>(info.param)) +
                                  (std::get<1>(info.param) ? "_gravity" : "_weightless");
                         });

class GrippersDrawApart : public ::testing::TestWithParam<std::tuple<int, double, bool>> {};

// Two grippers draw the yarn apart at a constant speed until it tears: the tear comes at an
// elongation of eps_b L0 and at the tension sigma_b pi r^2;
// before it, every edge's plastic strain is what the curve leaves at the edge's geometric strain
// (no spurious flow).
TEST_P(GrippersDrawApart, TearsOnceAtTheBreakingElongationAndForce) {
  const auto [num_vertices, dt, gravity] = GetParam();
  const YarnSpec spec = spanAlongX(num_vertices);
  const StressStrainCurve& curve = spec.material.curve;
  Simulator sim(heldParameters(dt, gravity), {spec});
  const std::uint32_t first = 0;
  const std::uint32_t last = sim.scene().globalVertex(0, -1);
  const Eigen::Vector3d first_start = sim.scene().vertices.position[first];
  const Eigen::Vector3d last_start = sim.scene().vertices.position[last];
  const double speed = 0.025;  // [m/s] each gripper: 0.05 m/s apart, strain rate 0.17 /s
  const double strain_step = 2.0 * speed * dt / spec.length;  // geometric strain per step [-]
  std::vector<double> largest_strain(sim.scene().edges.size(), 0.0);
  std::vector<TearEvent> events;
  double torn_at = -1.0;
  while (sim.time() < 1.0 && (torn_at < 0.0 || sim.time() < torn_at + 0.2)) {
    const double t = sim.time() + dt;
    sim.setKinematicTarget(first, first_start - Eigen::Vector3d(speed * t, 0.0, 0.0));
    sim.setKinematicTarget(last, last_start + Eigen::Vector3d(speed * t, 0.0, 0.0));
    sim.step();
    std::vector<TearEvent> now = sim.takeTearEvents();
    if (!now.empty() && torn_at < 0.0) torn_at = sim.time();
    events.insert(events.end(), now.begin(), now.end());
    if (torn_at >= 0.0) continue;
    const Scene& s = sim.scene();
    for (std::size_t e = 0; e < s.edges.size(); ++e) {
      const double length =
          (s.vertices.position[s.edges.vertex_b[e]] - s.vertices.position[s.edges.vertex_a[e]])
              .norm();
      const double geometric_strain = length / s.edges.original_rest_length[e] - 1.0;
      largest_strain[e] = std::max(largest_strain[e], geometric_strain);
      // Plastic strain is history: at least what the curve leaves at the strain now, at most what
      // it leaves at the largest strain so far, one step's increment later (it follows the stress
      // of the step) and within the constraint tolerance.
      const double slack = strain_step + 1e-6;
      const double now = plasticStrainAtStrain(curve, geometric_strain);
      const double most = plasticStrainAtStrain(curve, largest_strain[e]);
      ASSERT_GE(s.edges.plastic_strain[e], now - slack)
          << "N " << num_vertices << ", " << spanCaseName(dt, gravity) << ", edge " << e << ", t "
          << sim.time();
      ASSERT_LE(s.edges.plastic_strain[e], most + slack)
          << "N " << num_vertices << ", " << spanCaseName(dt, gravity) << ", edge " << e << ", t "
          << sim.time();
    }
  }
  // One tear: the pieces stay intact while the tear's unloading wave crosses them (Tearing),
  // though every edge of this yarn of uniform strength was at its breaking point.
  ASSERT_EQ(events.size(), 1u) << "N " << num_vertices << ", " << spanCaseName(dt, gravity);
  const double elongation = 2.0 * speed * events[0].time;
  const double breaking_elongation = curve.breakingStrain() * spec.length;
  EXPECT_NEAR(elongation, breaking_elongation, 0.02 * breaking_elongation)
      << "N " << num_vertices << ", " << spanCaseName(dt, gravity);
  const double breaking_force = curve.breakingStress() * kYarnArea;
  EXPECT_NEAR(events[0].tension, breaking_force, 0.02 * breaking_force)
      << "N " << num_vertices << ", " << spanCaseName(dt, gravity);
}

INSTANTIATE_TEST_SUITE_P(VerticesStepsAndGravity, GrippersDrawApart,
                         ::testing::Combine(::testing::Values(2, 3, 5, 10, 25),
                                            ::testing::Values(1.0e-3, 1.0e-4), ::testing::Bool()),
                         [](const ::testing::TestParamInfo<std::tuple<int, double, bool>>& info) {
                           return std::to_string(std::get<0>(info.param)) + "vertices_" +
                                  stepName(std::get<1>(info.param)) +
                                  (std::get<2>(info.param) ? "_gravity" : "_weightless");
                         });

// A taut span plucked sideways in the middle, against the same span with truly stiff springs.
TEST(HeldYarnReference, PluckedSpanMatchesTheStiffReference) {
  const double pretension = 2.0;  // [N]
  YarnSpec spec = spanAlongX(25);
  spec.pinned = {0, -1};
  const Scene scene = stretchedScene(spec, pretension);
  const double dt = 1.0e-3;
  Simulator sim(parametersWithoutGravity(dt), scene);
  StiffReferenceYarn reference(spec, Eigen::Vector3d::Zero());
  reference.setPositions(scene.vertices.position);
  const std::uint32_t middle = 12;
  const Eigen::Vector3d nudge(0.0, 2.0, 0.0);  // [m/s]
  sim.setVelocity(middle, nudge);
  reference.setVelocity(middle, nudge);
  double squared_error = 0.0;
  double peak = 0.0;
  std::size_t samples = 0;
  while (sim.time() < 0.2) {
    sim.step();
    reference.advance(dt);
    for (std::size_t e = 0; e < sim.scene().edges.size(); ++e) {
      const double truth = reference.tension(e);
      squared_error += std::pow(sim.scene().edges.tension[e] - truth, 2);
      peak = std::max(peak, truth);
      ++samples;
    }
  }
  const double rms = std::sqrt(squared_error / samples);
  std::cout << "plucked span: rms error " << rms << " N of peak " << peak << " N\n";
  EXPECT_LE(rms, 0.05 * peak) << "rms " << rms << " N, peak " << peak << " N";
}

}  // namespace
}  // namespace yarn_tearing::test
