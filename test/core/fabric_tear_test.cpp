// A trouser tear (ISO 13937-2's geometry, the tongues drawn apart in the fabric's plane): the tear
// runs along the slit's line, one weft segment after another, and the fabric stays stable
// throughout: every projection converges, no vertex moves faster than a released yarn's snap-back
// can make it, no break event reports more than the breaking force, and no intact segment is
// stretched more than a step's increment past its breaking strain.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fabric_support.hpp"
#include "yarn_tearing/core/lab/trouser_tear.hpp"

namespace yarn_tearing::test {
namespace {

struct TrouserRun {
  std::vector<TearEvent> events;
  double max_speed = 0.0;       ///< fastest vertex in any step [m/s]
  double max_overstrain = 0.0;  ///< largest intact segment strain / breaking strain [-]
  int unconverged_steps = 0;
};

/// runTrouserTear with the stability records of every step.
TrouserRun trouserTear(const SimulationParameters& p, const FabricSpec& spec, int slit_rows,
                       double speed, double duration) {
  TrouserRun run;
  const auto observe = [&run](const Simulator& sim) {
    const Scene& scene = sim.scene();
    if (!sim.lastHealth().projection_converged) ++run.unconverged_steps;
    for (const Eigen::Vector3d& v : scene.vertices.velocity) {
      run.max_speed = std::max(run.max_speed, v.norm());
    }
    for (std::size_t e = 0; e < scene.edges.size(); ++e) {
      if (!scene.edges.intact(e)) continue;
      const double length = (scene.vertices.position[scene.edges.vertex_b[e]] -
                             scene.vertices.position[scene.edges.vertex_a[e]])
                                .norm();
      const double strain = length / scene.edges.original_rest_length[e] - 1.0;
      const double breaking = scene.yarns[scene.edges.yarn[e]].material.curve.breakingStrain();
      run.max_overstrain = std::max(run.max_overstrain, strain / breaking);
    }
  };
  run.events = runTrouserTear(p, spec, {slit_rows, speed, duration}, observe).events;
  return run;
}

/// Without crimp, so that each warp yarn is a taut string from the held row to its grip: the
/// separation of the two strings next to the slit opens the weft segment between them at first
/// order in the grips' travel D, while the strings stretch only at second order (D^2 / 2 L^2).
FabricSpec trouserPatch() { return cottonPatch(12, 12, 0.06, 0.06); }

TEST(FabricTear, TrouserTearRunsAlongTheSlitsLineStablyWithinTheBreakingForce) {
  const FabricSpec spec = trouserPatch();
  const StressStrainCurve& curve = spec.weft.material.curve;
  // A released segment's snap-back leaves its yarn at the particle velocity sigma / (rho c),
  // c = sqrt(E / rho); twice that bounds what a tear can add to the grips' speed.
  const double release =
      curve.breakingStress() / std::sqrt(curve.youngsModulus() * spec.weft.material.density);
  const double breaking = breakingForce(spec.weft);
  for (const double dt : {1.0e-3, 1.0e-4}) {
    SimulationParameters p;
    p.time_step = dt;
    const TrouserRun run = trouserTear(p, spec, 4, 0.05, 0.4);
    const int middle = spec.ends / 2 - 1;
    // Up the line from the slit's tip, one pick after another, to the row next to the held one.
    ASSERT_EQ(run.events.size(), static_cast<std::size_t>(spec.picks - 5)) << "dt " << dt;
    for (std::size_t k = 0; k < run.events.size(); ++k) {
      const TearEvent& e = run.events[k];
      EXPECT_EQ(e.fabric, 0);
      EXPECT_EQ(e.segment.family, FabricFamily::kWeft) << "dt " << dt;
      EXPECT_EQ(e.segment.segment, static_cast<std::uint32_t>(middle)) << "dt " << dt;
      EXPECT_EQ(e.segment.yarn, static_cast<std::uint32_t>(spec.picks - 5) - k) << "dt " << dt;
    }

    EXPECT_EQ(run.unconverged_steps, 0) << "dt " << dt;
    EXPECT_LE(run.max_speed, 2.0 * release + 0.05) << "dt " << dt;
    for (const TearEvent& e : run.events) {
      EXPECT_LE(e.tension, breaking * (1.0 + 1e-12));
      EXPECT_GE(e.tension, 0.99 * breaking);  // a slow tear: at the yarn's own strength
      EXPECT_LE(e.strain, curve.breakingStrain() * (1.0 + 1e-12));
    }
    // Intact segments: at most their breaking length plus the stop's give.
    EXPECT_LE(run.max_overstrain, 1.0 + 1e-3) << "dt " << dt;
    std::printf("dt %g: fastest vertex %.3g m/s (bound %.3g), largest strain / breaking %.6f\n", dt,
                run.max_speed, 2.0 * release + 0.05, run.max_overstrain);
  }
}

}  // namespace
}  // namespace yarn_tearing::test
