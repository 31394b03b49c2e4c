// Recoil of a fabric: a plain-weave strip pulled along the warp until its warp yarns tear releases
// the elastic energy its edges stored, sum 1/2 T^2 L0 / (E A). The pieces fly back at about
// sigma_b / (rho c) (~140 m/s); the strip is long enough (3 m) that they are still flying a 1e-2 s
// step after the tear. Compared with the stored energy (at least half of it becomes motion, the
// yarns' standard of recoil_test.cpp) and with the same tear taken in 16 times finer substeps
// (never more than it: the compliant projection only takes energy away).
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "fabric_support.hpp"

namespace yarn_tearing::test {
namespace {

/// Elastic energy of the intact edges, 1/2 T^2 L0 / (E f A) [J] (f the rate factor).
double storedElasticEnergy(const Scene& scene) {
  const EdgeSet& edges = scene.edges;
  double energy = 0.0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e)) continue;
    const double stiffness = scene.yarns[edges.yarn[e]].material.curve.youngsModulus() *
                             edges.rate_factor[e] * edges.area[e];
    energy += 0.5 * edges.tension[e] * edges.tension[e] * edges.original_rest_length[e] / stiffness;
  }
  return energy;
}

struct StripRecoil {
  double stored = 0.0;     ///< elastic energy just before the first tear [J]
  double peak = 0.0;       ///< largest kinetic energy at the ends of the steps in kWindow [J]
  double grip_work = 0.0;  ///< bound on the grips' work over the window, sum |F| |dx| [J]
  std::vector<TearEvent> events;  ///< every tear, from the first on
};

/// Time after the tear the kinetic energy is watched in [s]: the 3 m pieces, flying back at
/// ~140 m/s, reach their holders after about 20 ms.
constexpr double kWindow = 0.03;

/// Two warp ends 5 mm apart, 3 m along the warp (25 picks), no gravity, first row pinned, the
/// last row drawn along the warp at 0.1 m/s until the warp tears, then watched for kWindow.
StripRecoil pullStripUntilItTears(double dt, int recoil_substeps) {
  SimulationParameters p = parametersWithoutGravity(dt);
  p.recoil_substeps = recoil_substeps;
  const FabricSpec spec = cottonPatch(2, 25, 0.005, 3.0);
  Simulator sim(p, {}, {spec});
  const Scene& scene = sim.scene();
  const Eigen::Vector3d warp(0.0, 0.0, -1.0);
  const std::vector<std::uint32_t> grip = lastRow(scene);
  const std::vector<Eigen::Vector3d> start = positionsOf(scene, grip);
  const double speed = 0.1;  // [m/s]
  StripRecoil r;
  double tear_time = -1.0;
  for (int i = 1; i < 1000000; ++i) {
    std::vector<Eigen::Vector3d> before;
    for (std::size_t k = 0; k < grip.size(); ++k) {
      before.push_back(scene.vertices.position[grip[k]]);
      sim.setKinematicTarget(grip[k], start[k] + speed * i * dt * warp);
    }
    // The step before the tear's: in the tear's own step the edges at their breaking length
    // feel the length stop's force (doc/method.md, "Breaking-length stop"). One step's pull adds at
    // most 1 % to it.
    const double stored_before = storedElasticEnergy(scene);
    sim.step();
    // (Without substeps an unconverged step is not taken again: doc/method.md,
    // "Substeps for an unconverged step".)
    if (recoil_substeps > 1) {
      EXPECT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    }
    const std::vector<TearEvent> now = sim.takeTearEvents();
    if (tear_time < 0.0 && !now.empty()) {
      tear_time = sim.time();
      r.stored = stored_before;
    } else if (tear_time >= 0.0) {
      r.peak = std::max(r.peak, kineticEnergy(sim));
      for (std::size_t k = 0; k < grip.size(); ++k) {
        r.grip_work += sim.supportForce(grip[k]).norm() *
                       (scene.vertices.position[grip[k]] - before[k]).norm();
      }
    }
    r.events.insert(r.events.end(), now.begin(), now.end());
    if (tear_time >= 0.0 && sim.time() >= tear_time + kWindow - 0.5 * dt) break;
  }
  return r;
}

TEST(FabricRecoil, TornStripTurnsAtLeastHalfItsElasticEnergyIntoMotion) {
  for (const double dt : {1.0e-4, 1.0e-3, 1.0e-2}) {
    const int substeps = SimulationParameters{}.recoil_substeps;
    const StripRecoil r = pullStripUntilItTears(dt, substeps);
    const StripRecoil fine = pullStripUntilItTears(dt, 16 * substeps);
    std::cout << "dt " << dt << ": peak kinetic energy " << r.peak / r.stored
              << " of the stored elastic energy " << r.stored << " J (16 x finer substeps "
              << fine.peak / fine.stored << ")\n";
    // Each warp end tears once, no weft segment.
    ASSERT_EQ(r.events.size(), 2u) << "dt " << dt;
    EXPECT_NE(r.events[0].segment.yarn, r.events[1].segment.yarn) << "dt " << dt;
    for (const TearEvent& e : r.events) {
      EXPECT_EQ(e.segment.family, FabricFamily::kWarp) << "dt " << dt;
    }
    EXPECT_GE(r.peak, 0.5 * r.stored) << "dt " << dt;
    EXPECT_LE(r.peak, r.stored + r.grip_work) << "dt " << dt;
    EXPECT_LE(r.peak, 1.01 * fine.peak) << "dt " << dt;
  }
}

TEST(FabricRecoil, WithoutSubstepsTheStripLosesIt) {
  for (const double dt : {1.0e-3, 1.0e-2}) {
    const StripRecoil r = pullStripUntilItTears(dt, 1);
    EXPECT_LT(r.peak, 0.5 * r.stored) << "dt " << dt;
  }
}

}  // namespace
}  // namespace yarn_tearing::test
