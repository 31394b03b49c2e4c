// Local recoil: the step after a tear substeps only the yarn within the elastic wave's reach of
// the tear (RecoilRegion), the rest in one step. Compared with the same step substepping the
// whole scene (SimulationParameters::local_recoil = false) from the same state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

/// What the two recoils differ by after the same steps.
struct Difference {
  double kinetic = 0.0;        ///< |E_local - E_whole| / E_whole [-]
  double position = 0.0;       ///< largest vertex distance [m]
  double tension = 0.0;        ///< largest edge tension difference over the breaking force [-]
  std::size_t substepped = 0;  ///< vertices the local recoil's first step substepped [-]
  std::size_t vertices = 0;    ///< vertices of the scene [-]
};

/// Steps `torn` (its recoil pending) `steps` times with and without local recoil; a kinematic
/// `drawn` vertex keeps moving at `draw` [m/s]. `breaking_force` [N] scales the tensions.
Difference compareRecoils(const Simulator& torn, int steps, double breaking_force,
                          std::int64_t drawn = -1,
                          const Eigen::Vector3d& draw = Eigen::Vector3d::Zero()) {
  Simulator local = torn;
  Simulator whole = torn;
  SimulationParameters p = torn.parameters();
  p.local_recoil = false;
  whole.setParameters(p);
  Difference d;
  d.vertices = torn.scene().vertices.size();
  for (int i = 0; i < steps; ++i) {
    for (Simulator* sim : {&local, &whole}) {
      if (drawn >= 0) {
        const auto v = static_cast<std::uint32_t>(drawn);
        sim->setKinematicTarget(
            v, sim->scene().vertices.position[v] + torn.parameters().time_step * draw);
      }
      sim->step();
    }
    if (i == 0) d.substepped = local.lastHealth().substepped_vertices;
    EXPECT_TRUE(local.takeTearEvents().empty());
    EXPECT_TRUE(whole.takeTearEvents().empty());
  }
  const double whole_kinetic = kineticEnergy(whole);
  d.kinetic = std::abs(kineticEnergy(local) - whole_kinetic) / whole_kinetic;
  const Scene& a = local.scene();
  const Scene& b = whole.scene();
  for (std::size_t v = 0; v < a.vertices.size(); ++v) {
    d.position = std::max(d.position, (a.vertices.position[v] - b.vertices.position[v]).norm());
  }
  for (std::size_t e = 0; e < a.edges.size(); ++e) {
    d.tension =
        std::max(d.tension, std::abs(a.edges.tension[e] - b.edges.tension[e]) / breaking_force);
  }
  return d;
}

void report(const char* scene, const Difference& d) {
  std::cout << scene << ": local recoil substepped " << d.substepped << " of " << d.vertices
            << " vertices; kinetic energy within " << d.kinetic << ", positions within "
            << d.position << " m, tensions within " << d.tension << " F_b\n";
}

/// Reports `d` and checks that the local recoil substepped part of the scene and stayed within
/// the whole-scene recoil's kinetic energy [-], positions [m] and tensions [F_b].
void expectLikeTheWholeScene(const char* scene, const Difference& d) {
  report(scene, d);
  EXPECT_GT(d.substepped, 0u) << scene;
  EXPECT_LE(d.kinetic, 3.0e-4) << scene;
  EXPECT_LE(d.position, 1.0e-3) << scene;
  EXPECT_LE(d.tension, 0.02) << scene;
}

/// A 15 m cotton yarn of 1200 vertices along +x, vertex 0 pinned, its last drawn at 0.2 m/s
/// from just below the breaking strain of its weak middle edge (a fifth of the yarn's strength,
/// so it tears in the elastic range), stepped until that edge tears.
TEST(LocalRecoil, MatchesTheWholeSceneRecoilOfADrawnYarn) {
  YarnSpec spec = hangingYarn();
  spec.num_vertices = 1200;
  spec.length = 0.0125 * (spec.num_vertices - 1);
  spec.direction = Eigen::Vector3d::UnitX();
  Scene scene = buildScene({spec});
  const std::uint32_t weak = 600;
  const double factor = 0.2;
  scene.edges.strength_factor[weak] = factor;
  const StressStrainCurve& curve = spec.material.curve;
  const double breaking_strain = curve.strainAtStress(factor * curve.breakingStress());
  for (Eigen::Vector3d& x : scene.vertices.position) x *= 1.0 + 0.99 * breaking_strain;
  Simulator sim(parametersWithoutGravity(), scene);
  const std::uint32_t drawn = sim.scene().globalVertex(0, -1);
  const Eigen::Vector3d draw(0.2, 0.0, 0.0);
  while (!sim.recoilPending() && sim.time() < 1.0) {
    const Eigen::Vector3d x = sim.scene().vertices.position[drawn];
    sim.setKinematicTarget(drawn, x + sim.parameters().time_step * draw);
    sim.step();
  }
  const std::vector<TearEvent> events = sim.takeTearEvents();
  ASSERT_EQ(events.size(), 1u);
  ASSERT_EQ(events[0].edge, weak);
  const double breaking_force = factor * curve.breakingStress() * spec.area();
  for (int steps : {1, 3}) {
    const Difference d = compareRecoils(sim, steps, breaking_force, drawn, draw);
    expectLikeTheWholeScene(steps == 1 ? "drawn yarn, 1 step" : "drawn yarn, 3 steps", d);
    EXPECT_LT(2 * d.substepped, d.vertices);
  }
}

/// The benchmark's scene: a 12.5 m cotton yarn of 1000 vertices with a 10 g weight, hanging
/// settled from its pinned top, its end pulled at twice the breaking force until it tears.
TEST(LocalRecoil, MatchesTheWholeSceneRecoilOfAHangingYarnPulledApart) {
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
  for (int steps : {1, 3}) {
    const Difference d = compareRecoils(sim, steps, breaking_force);
    expectLikeTheWholeScene(
        steps == 1 ? "pulled hanging yarn, 1 step" : "pulled hanging yarn, 3 steps", d);
  }
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
