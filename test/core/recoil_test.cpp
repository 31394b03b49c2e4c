// Recoil: a tear releases the elastic energy the yarn stored, 1/2 T^2 L0 / (E A). The snap-back
// wave (sqrt(E / rho), ~2 km/s) crosses a 0.3 m yarn in 0.15 ms, far inside a 1 ms step; the step
// after a tear is therefore taken in recoil_substeps substeps. Compared with the stiff reference
// (springs E A / L0 at a tiny step) cut at the same edge from the same tension.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "test_support.hpp"
#include "yarn_tearing/core/lab/stiff_reference_yarn.hpp"

namespace yarn_tearing::test {
namespace {

struct Recoil {
  double stored = 0.0;     ///< elastic energy at the tear, 1/2 T^2 L0 / (E A) [J]
  double peak = 0.0;       ///< largest kinetic energy at the ends of the 3 steps after it [J]
  double reference = 0.0;  ///< the stiff reference's peak over the same 3 steps [J]
  int substeps = 0;        ///< substeps of the step after the tear [-]
};

/// Vertex 0 pinned, the last vertex drawn along +x until the yarn tears at time step `dt` [s].
Recoil drawUntilTearAndRecoil(int vertices, double dt, int recoil_substeps) {
  const Material material = cottonLike();
  YarnSpec spec = hangingYarn(material);
  spec.num_vertices = vertices;
  spec.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  SimulationParameters p = parametersWithoutGravity(dt);
  p.recoil_substeps = recoil_substeps;
  Simulator sim(p, {spec});
  const std::uint32_t grasped = sim.scene().globalVertex(0, -1);
  const Eigen::Vector3d start = sim.scene().vertices.position[grasped];
  const double speed = 0.05;  // [m/s]
  std::vector<TearEvent> events;
  while (events.empty() && sim.time() < 2.0) {
    sim.setKinematicTarget(grasped, start + Eigen::Vector3d(speed * (sim.time() + dt), 0.0, 0.0));
    sim.step();
    events = sim.takeTearEvents();
  }
  Recoil result;
  if (events.size() != 1u) {
    ADD_FAILURE() << events.size() << " tears";
    return result;
  }
  const double stiffness = material.curve.youngsModulus() * spec.area();  // E A [N]
  const double tension = events[0].tension;
  result.stored = 0.5 * tension * tension * spec.length / stiffness;
  for (int i = 0; i < 3; ++i) {
    sim.setKinematicTarget(grasped, start + Eigen::Vector3d(speed * (sim.time() + dt), 0.0, 0.0));
    sim.step();
    if (i == 0) result.substeps = sim.lastHealth().substeps;
    result.peak = std::max(result.peak, kineticEnergy(sim));
  }

  // The stiff reference held at both ends at the same tension, cut at the same edge.
  YarnSpec held = spec;
  held.pinned = {0, -1};
  StiffReferenceYarn reference(held, Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> stretched = reference.positions();
  for (Eigen::Vector3d& x : stretched) x *= 1.0 + tension / stiffness;
  reference.setPositions(stretched);
  reference.cut(events[0].edge);
  for (int i = 0; i < 300; ++i) {  // its true peak, sampled every dt / 100
    reference.advance(0.01 * dt);
    result.reference = std::max(result.reference, reference.kineticEnergy());
  }
  return result;
}

TEST(Recoil, ATearReleasesAtLeastHalfItsElasticEnergyAtOneMillisecond) {
  for (int n : {5, 25, 100}) {
    const Recoil r = drawUntilTearAndRecoil(n, 1.0e-3, SimulationParameters{}.recoil_substeps);
    std::cout << n << " vertices: peak kinetic energy " << r.peak / r.stored
              << " of the stored elastic energy (stiff reference " << r.reference / r.stored
              << ")\n";
    // A chain of 5 lumped masses keeps a quarter of it in its own vibration even at its peak.
    if (n >= 25) {
      EXPECT_GE(r.reference, 0.95 * r.stored) << n << " vertices";
    }
    EXPECT_GE(r.peak, 0.5 * r.stored) << n << " vertices";
    EXPECT_LE(r.peak, 1.01 * r.reference) << n << " vertices";
  }
}

// The step after the tear takes substeps of dt / recoil_substeps only while the pieces unload
// (the elastic wave crosses a piece no longer than the stretched yarn, L (1 + eps_b) / c), then
// at most 4 substeps growing to the step's end (doc/method.md, "Recoil substeps").
TEST(Recoil, FineSubstepsOnlyWhileThePiecesUnload) {
  const double dt = 1.0e-3;
  const int fine = SimulationParameters{}.recoil_substeps;
  const Recoil r = drawUntilTearAndRecoil(25, dt, fine);
  const Material material = cottonLike();
  const double wave_speed = std::sqrt(material.curve.youngsModulus() / material.density);
  const double unloading = hangingYarn().length * (1.0 + 0.071) / wave_speed;  // [s]
  const int unloading_substeps = static_cast<int>(std::ceil(unloading / (dt / fine)));
  EXPECT_GT(r.substeps, 1);
  EXPECT_LE(r.substeps, unloading_substeps + 4);
  EXPECT_LT(r.substeps, fine / 4);
}

TEST(Recoil, WithoutSubstepsOneStepLosesIt) {
  const Recoil r = drawUntilTearAndRecoil(25, 1.0e-3, 1);
  EXPECT_LT(r.peak, 0.05 * r.stored);
}

}  // namespace
}  // namespace yarn_tearing::test
