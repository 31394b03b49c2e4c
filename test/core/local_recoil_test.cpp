// Local recoil: the step after a yarn's tear takes only the yarn within the elastic wave's reach
// of the tear (RecoilRegion) through the release wave, the rest of the scene in one step. Checked
// against the closed form of a bar released at a cut and against the same wave over the whole
// yarn from the same state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "test_support.hpp"
#include "yarn_tearing/core/simulation/recoil_wave.hpp"

namespace yarn_tearing::test {
namespace {

/// Kinetic energy [J] of the free vertices of `scene`, and the fastest of them [m/s] relative to
/// `reference` (per vertex, or none).
struct Motion {
  double kinetic = 0.0;
  double fastest = 0.0;
};

Motion motionOf(const Scene& scene, const std::vector<Eigen::Vector3d>* reference = nullptr) {
  const VertexSet& v = scene.vertices;
  Motion m;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v.isSupport(i)) continue;
    const Eigen::Vector3d u =
        reference ? Eigen::Vector3d(v.velocity[i] - (*reference)[i]) : v.velocity[i];
    m.kinetic += 0.5 * v.mass[i] * v.velocity[i].squaredNorm();
    m.fastest = std::max(m.fastest, u.norm());
  }
  return m;
}

/// A 15 m cotton yarn of 1200 vertices along +x, vertex 0 pinned, its last drawn at 0.2 m/s
/// from just below the breaking strain of its weak middle edge (a fifth of the yarn's strength,
/// so it tears in the elastic range), stepped until that edge tears, then once more. A bar under
/// tension T released at a cut unloads behind a front running at c = sqrt(E / rho) from it;
/// behind the front the material moves at c T / (E A) away from the cut, all its strain energy
/// turned kinetic: after t, both pieces together hold T^2 c t / (E A) more kinetic energy. The
/// discrete chain's front rings, its fastest vertex up to 3 % faster (doc/method.md, "Recoil
/// wave"). At Δt = 1e-4 [s] and 1e-3 [s] the wave reaches less than half the yarn; at 1e-2 [s] it
/// would cross it, and the step is taken in whole-scene substeps.
class DrawnYarnRecoil : public ::testing::TestWithParam<double> {};

TEST_P(DrawnYarnRecoil, ThePiecesFlyAsTheReleaseWaveHasIt) {
  const YarnSpec spec = hangingYarn();
  const std::uint32_t weak = 600;
  Simulator sim(parametersWithoutGravity(GetParam()), weakEdgeYarnScene(1200, weak, 0.2));
  const std::uint32_t drawn = sim.scene().globalVertex(0, -1);
  const Eigen::Vector3d draw(0.2, 0.0, 0.0);
  const auto drawOn = [&sim, drawn, &draw] {
    const Eigen::Vector3d x = sim.scene().vertices.position[drawn];
    sim.setKinematicTarget(drawn, x + sim.parameters().time_step * draw);
  };
  while (!sim.recoilPending() && sim.time() < 0.1) {
    drawOn();
    sim.step();
  }
  const std::vector<TearEvent> events = sim.takeTearEvents();
  ASSERT_EQ(events.size(), 1u);
  ASSERT_EQ(events[0].edge, weak);
  const std::vector<Eigen::Vector3d> before = sim.scene().vertices.velocity;
  const double kinetic_before = motionOf(sim.scene()).kinetic;
  drawOn();
  sim.step();
  EXPECT_TRUE(sim.takeTearEvents().empty());
  EXPECT_GT(sim.lastHealth().substepped_vertices, 0u);
  EXPECT_LT(2 * sim.lastHealth().substepped_vertices, sim.scene().vertices.size());

  const StressStrainCurve& curve = spec.material.curve;
  const double stiffness = curve.youngsModulus() * spec.area();  // E A [N]
  const double speed = std::sqrt(curve.youngsModulus() / spec.material.density);
  const double t = sim.parameters().time_step;
  const double released = events[0].tension * events[0].tension * speed * t / stiffness;
  const Motion motion = motionOf(sim.scene(), &before);
  std::cout << "kinetic energy gained " << motion.kinetic - kinetic_before << " J, closed form "
            << released << " J; fastest vertex " << motion.fastest << " m/s faster, c T / (E A) "
            << speed * events[0].tension / stiffness << " m/s\n";
  EXPECT_NEAR(motion.kinetic - kinetic_before, released, 0.02 * released);
  EXPECT_LE(motion.fastest, 1.05 * speed * events[0].tension / stiffness);
}

INSTANTIATE_TEST_SUITE_P(LocalRecoil, DrawnYarnRecoil, ::testing::Values(1.0e-4, 1.0e-3));

/// The benchmark's scene: a 12.5 m cotton yarn of 1000 vertices with a 10 g weight, hanging
/// settled from its pinned top, its end pulled at twice the breaking force until it tears. The
/// step after the tear, which moves a quarter of the yarn by the release wave, against the same
/// wave integrated over the whole yarn from the same state.
TEST(LocalRecoil, MatchesTheWaveOverTheWholeYarn) {
  YarnSpec spec = hangingYarn();
  spec.num_vertices = 1000;
  spec.length = 0.0125 * (spec.num_vertices - 1);
  spec.end_mass = 0.01;
  SimulationParameters p;
  p.air_damping = 0.05;
  Simulator sim(p, {spec});
  for (int i = 0; i < 200; ++i) sim.step();
  const double breaking_force = spec.material.curve.breakingStress() * spec.area();
  sim.setAppliedForce(sim.scene().globalVertex(0, -1),
                      Eigen::Vector3d(0.0, 0.0, -2.0 * breaking_force));
  while (!sim.recoilPending() && sim.time() < 1.0) sim.step();
  ASSERT_EQ(sim.takeTearEvents().size(), 1u);
  Scene whole = sim.scene();
  const std::vector<double> from_the_start(whole.vertices.size(), 0.0);
  std::vector<double> tension;
  const std::vector<Eigen::Vector3d> acceleration = startAccelerations(p, whole);
  ASSERT_TRUE(
      integrateRecoilWave(p, from_the_start, acceleration, p.time_step, whole, tension).completed);
  sim.step();
  const std::size_t substepped = sim.lastHealth().substepped_vertices;
  EXPECT_GT(substepped, 0u);
  EXPECT_LT(2 * substepped, whole.vertices.size());

  const Scene& local = sim.scene();
  double position = 0.0;    // largest vertex distance [m]
  double difference = 0.0;  // largest tension difference [F_b]
  for (std::size_t v = 0; v < local.vertices.size(); ++v) {
    position = std::max(position, (local.vertices.position[v] - whole.vertices.position[v]).norm());
  }
  for (std::size_t e = 0; e < local.edges.size(); ++e) {
    difference =
        std::max(difference, std::abs(local.edges.tension[e] - tension[e]) / breaking_force);
  }
  const double kinetic = motionOf(whole).kinetic;
  const double gap = std::abs(motionOf(local).kinetic - kinetic) / kinetic;
  std::cout << "local recoil moved " << substepped << " of " << whole.vertices.size()
            << " vertices; kinetic energy within " << gap << ", positions within " << position
            << " m, tensions within " << difference << " F_b of the wave over the whole yarn\n";
  EXPECT_LE(gap, 0.01);
  EXPECT_LE(position, 1.0e-3);
  EXPECT_LE(difference, 0.02);
}

/// Two like hanging yarns of 600 vertices whose end forces ramp up alike, the second's one step
/// later: the second tears in the step that resolves the first's recoil, which a local recoil
/// then takes in whole-scene substeps. Both recoils give the same break events, once each.
TEST(LocalRecoil, ATearDuringTheRecoilGivesTheSameEventsOnce) {
  YarnSpec first = hangingYarn();
  first.num_vertices = 600;
  first.length = 0.0125 * (first.num_vertices - 1);
  first.end_mass = 0.01;
  YarnSpec second = first;
  second.name = "second";
  second.start = Eigen::Vector3d(0.1, 0.0, 0.0);
  SimulationParameters p;
  p.air_damping = 0.05;
  Simulator local(p, {first, second});
  p.local_recoil = false;
  Simulator whole(p, {first, second});
  const double breaking_force = first.material.curve.breakingStress() * first.area();
  const double ramp = 40.0 * breaking_force;  // [N/s]
  std::vector<TearEvent> local_events;
  std::vector<TearEvent> whole_events;
  for (int i = 0; i < 100; ++i) {
    for (Simulator* sim : {&local, &whole}) {
      for (std::size_t yarn = 0; yarn < 2; ++yarn) {
        const double t = std::max(0.0, sim->time() - static_cast<double>(yarn) * p.time_step);
        sim->setAppliedForce(sim->scene().globalVertex(yarn, -1),
                             Eigen::Vector3d(0.0, 0.0, -ramp * t));
      }
      sim->step();
    }
    const std::vector<TearEvent> events = local.takeTearEvents();
    if (local_events.size() == 1 && !events.empty()) {
      EXPECT_EQ(local.lastHealth().substepped_vertices, local.scene().vertices.size());
    }
    local_events.insert(local_events.end(), events.begin(), events.end());
    for (const TearEvent& e : whole.takeTearEvents()) whole_events.push_back(e);
  }
  ASSERT_EQ(local_events.size(), 2u);
  ASSERT_EQ(whole_events.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(local_events[i].yarn, whole_events[i].yarn);
    EXPECT_EQ(local_events[i].edge, whole_events[i].edge);
    EXPECT_NEAR(local_events[i].time, whole_events[i].time, p.time_step / p.recoil_substeps);
    EXPECT_LE(local_events[i].tension, 1.0001 * breaking_force);
  }
  std::cout << "tears at " << local_events[0].time << " s and " << local_events[1].time
            << " s (whole-scene recoil: " << whole_events[0].time << ", " << whole_events[1].time
            << ")\n";
  EXPECT_GT(local_events[1].time, local_events[0].time);
  EXPECT_LE(local_events[1].time, local_events[0].time + p.time_step);
}

}  // namespace
}  // namespace yarn_tearing::test
