// A fabric hit by a sudden point force far beyond a segment's breaking force (a robot yanking a
// corner, a force message sent as a step): every step converges (a step whose projection does
// not is taken again in substeps), the outcome does not depend on the step the
// force arrives in, no break event reports more than the yarn's breaking force or strain, and no
// vertex gains more momentum in a step than its loads can give it.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "fabric_support.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing::test {
namespace {

/// "warp 0/4": the family, yarn and segment a fabric's event names.
std::string describe(const TearEvent& e) {
  return std::string(familyName(e.segment.family)) + " " + std::to_string(e.segment.yarn) + "/" +
         std::to_string(e.segment.segment);
}

struct StepLoadRun {
  int unconverged_steps = 0;   ///< steps whose projection did not converge [-]
  int substepped_steps = 0;    ///< steps taken in substeps (a tear's recoil or a retry) [-]
  double largest_kick = 0.0;   ///< max over free vertices and steps of |m dv| / (dt * bound) [-]
  std::set<std::string> torn;  ///< describe() of every event
  std::vector<TearEvent> events;
};

/// A 7 x 6 cotton patch (6 x 5 cm) hanging from its first row for 0.3 s plus `delay` steps, then
/// a step force `force` [N] along -z on its last row's first vertex for 0.05 s.
StepLoadRun yank(double force, double dt, int delay) {
  FabricSpec spec = cottonPatch(7, 6, 0.06, 0.05);
  spec.warp_crimp = 0.02;
  spec.weft_crimp = 0.02;
  SimulationParameters p;
  p.time_step = dt;
  p.air_damping = 1.0e-3;
  Simulator sim(p, {}, {spec});
  const Scene& scene = sim.scene();
  for (int i = 0; i < static_cast<int>(0.3 / dt) + delay; ++i) sim.step();
  const std::uint32_t loaded = scene.fabricVertex(0, -1, 0);
  sim.setAppliedForce(loaded, Eigen::Vector3d(0.0, 0.0, -force));

  StepLoadRun run;
  const double breaking = breakingForce(spec.weft);  // warp and weft alike
  for (int i = 0; i < static_cast<int>(0.05 / dt); ++i) {
    const std::vector<Eigen::Vector3d> velocity = scene.vertices.velocity;
    const std::vector<std::uint8_t> broken = scene.edges.broken;
    sim.step();
    const StepHealth& health = sim.lastHealth();
    if (!health.projection_converged) ++run.unconverged_steps;
    if (health.substeps > 1) ++run.substepped_steps;
    // What the loads can give a vertex in a step: its external force and weight, and each of its
    // edges intact at the step's start pulling at most at its breaking force.
    std::vector<double> bound(scene.vertices.size(), 0.0);
    for (std::size_t v = 0; v < bound.size(); ++v) {
      bound[v] = (scene.vertices.applied_force[v] -
                  Eigen::Vector3d(0.0, 0.0, scene.vertices.mass[v] * kGravity))
                     .norm();
    }
    for (std::size_t e = 0; e < broken.size(); ++e) {
      if (broken[e]) continue;
      bound[scene.edges.vertex_a[e]] += breaking;
      bound[scene.edges.vertex_b[e]] += breaking;
    }
    for (std::size_t v = 0; v < bound.size(); ++v) {
      if (scene.vertices.isSupport(v)) continue;
      const double kick =
          scene.vertices.mass[v] * (scene.vertices.velocity[v] - velocity[v]).norm();
      run.largest_kick = std::max(run.largest_kick, kick / (dt * bound[v]));
    }
    for (const TearEvent& e : sim.takeTearEvents()) {
      run.torn.insert(describe(e));
      run.events.push_back(e);
    }
  }
  EXPECT_TRUE(allFinite(sim));
  return run;
}

TEST(FabricStepLoad, SuddenForcesFarBeyondTheBreakingForceConvergeAndTearWithinIt) {
  const FabricSpec spec = cottonPatch(7, 6, 0.06, 0.05);
  const double breaking = breakingForce(spec.weft);
  const double breaking_strain = spec.weft.material.curve.breakingStrain();
  for (const double dt : {1.0e-4, 1.0e-3, 1.0e-2}) {
    for (const double multiple : {1.5, 3.0, 10.0}) {
      SCOPED_TRACE("dt " + std::to_string(dt) + ", force " + std::to_string(multiple) +
                   " x the breaking force");
      for (int delay = 0; delay < 3; ++delay) {
        const StepLoadRun run = yank(multiple * breaking, dt, 37 * delay);
        EXPECT_EQ(run.unconverged_steps, 0);
        ASSERT_FALSE(run.events.empty());
        EXPECT_LE(run.largest_kick, 1.0);
        for (const TearEvent& e : run.events) {
          EXPECT_LE(e.tension, breaking * (1.0 + 1e-9));
          EXPECT_LE(e.strain, breaking_strain * (1.0 + 1e-9));
        }
        // The loaded vertex is torn out first, whatever the step and the step the force arrives
        // in: its warp segment, then its weft segment (what tears after depends on how the
        // patch swings at that moment).
        ASSERT_GE(run.events.size(), 2u);
        EXPECT_EQ(describe(run.events[0]), "warp 0/4");
        EXPECT_EQ(run.torn.count("weft 5/0"), 1u);
        std::printf(
            "dt %g, %.1f x breaking force, delay %d: %zu tears (%d substepped steps), "
            "largest kick %.3f of the bound\n",
            dt, multiple, delay, run.events.size(), run.substepped_steps, run.largest_kick);
      }
    }
  }
}

}  // namespace
}  // namespace yarn_tearing::test
