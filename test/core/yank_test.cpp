// A yarn or fabric yanked by a step force far beyond a segment's breaking force (a robot
// jerking a corner, a force message sent as a step): no intact segment carries more than its
// breaking force except in a step in which its piece tears (a step tears one segment of a piece;
// the others keep the force that step's stop gave them), and no free vertex without an applied
// force moves faster than twice the fastest snap-back a yarn can give it, c eps_b = sqrt(E / rho)
// eps_b, whatever the step and the recoil substeps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fabric_support.hpp"
#include "yarn_tearing/core/model/connected_pieces.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing::test {
namespace {

struct YankCase {
  double dt;            ///< [s]
  int recoil_substeps;  ///< [-]
};

std::string yankCaseName(const testing::TestParamInfo<YankCase>& info) {
  return stepName(info.param.dt) + "_recoil" + std::to_string(info.param.recoil_substeps);
}

/// What a yank did, over the steps after the force arrived.
struct YankRun {
  double largest_overload = 0.0;  ///< max tension / breaking force of a segment in a piece that
                                  ///< did not tear in the step [-]
  double fastest = 0.0;           ///< max speed of a free vertex with no applied force [m/s]
  int tears = 0;                  ///< break events [-]
};

/// Steps `sim` for `duration` [s] after a step force `force` [N] along -z on `loaded`, and reads
/// each step's end against the segments' breaking force `breaking` [N].
YankRun yank(Simulator& sim, std::uint32_t loaded, double force, double breaking, double duration) {
  const Scene& scene = sim.scene();
  sim.setAppliedForce(loaded, Eigen::Vector3d(0.0, 0.0, -force));
  YankRun run;
  const int steps = static_cast<int>(std::lround(duration / sim.parameters().time_step));
  for (int i = 0; i < steps; ++i) {
    const std::vector<std::uint8_t> broken = scene.edges.broken;
    ConnectedPieces pieces;  // as the step begins
    pieces.build(scene.edges, scene.vertices.size());
    sim.step();
    std::vector<std::uint8_t> tore(scene.vertices.size(), 0);  // per piece root
    for (std::size_t e = 0; e < broken.size(); ++e) {
      if (!broken[e] && scene.edges.broken[e]) tore[pieces.root(scene.edges.vertex_a[e])] = 1;
    }
    for (std::size_t e = 0; e < broken.size(); ++e) {
      if (!scene.edges.intact(e) || tore[pieces.root(scene.edges.vertex_a[e])]) continue;
      run.largest_overload = std::max(run.largest_overload, scene.edges.tension[e] / breaking);
    }
    for (std::size_t v = 0; v < scene.vertices.size(); ++v) {
      if (scene.vertices.isSupport(v) || !scene.vertices.applied_force[v].isZero()) continue;
      run.fastest = std::max(run.fastest, scene.vertices.velocity[v].norm());
    }
    run.tears += static_cast<int>(sim.takeTearEvents().size());
  }
  EXPECT_TRUE(allFinite(sim));
  return run;
}

/// The fastest snap-back from the breaking strain, c eps_b = sqrt(E / rho) eps_b [m/s].
double snapBackSpeed(const Material& material) {
  return std::sqrt(material.curve.youngsModulus() / material.density) *
         material.curve.breakingStrain();
}

class Yank : public testing::TestWithParam<YankCase> {
 protected:
  SimulationParameters parameters() const {
    SimulationParameters p;
    p.time_step = GetParam().dt;
    p.recoil_substeps = GetParam().recoil_substeps;
    p.air_damping = 1.0e-3;
    return p;
  }

  /// Checks a run against the bounds and prints it.
  static void expectWithinStrength(const YankRun& run, const Material& material, const char* what) {
    std::printf("%s: %d tears, largest overload %.3f F_b, fastest %.1f m/s (c eps_b %.1f m/s)\n",
                what, run.tears, run.largest_overload, run.fastest, snapBackSpeed(material));
    EXPECT_GE(run.tears, 1);
    EXPECT_LE(run.largest_overload, 1.0 + 1e-9);
    EXPECT_LE(run.fastest, 2.0 * snapBackSpeed(material));
  }
};

TEST_P(Yank, FabricCornerNeitherOverloadsASegmentNorFlingsAVertex) {
  // A 7 x 6 cotton patch (6 x 5 cm, 2 % crimp) hanging from its first row, settled 0.3 s; its
  // last row's first vertex then pulled at 3 and 10 x a segment's breaking force for 50 ms.
  FabricSpec spec = cottonPatch(7, 6, 0.06, 0.05);
  spec.warp_crimp = 0.02;
  spec.weft_crimp = 0.02;
  const double breaking = breakingForce(spec.weft);  // warp and weft alike
  for (const double multiple : {3.0, 10.0}) {
    SCOPED_TRACE(std::to_string(multiple) + " x the breaking force");
    Simulator sim(parameters(), {}, {spec});
    const int settle = static_cast<int>(std::lround(0.3 / GetParam().dt));
    for (int i = 0; i < settle; ++i) sim.step();
    const std::uint32_t loaded = sim.scene().fabricVertex(0, -1, 0);
    expectWithinStrength(yank(sim, loaded, multiple * breaking, breaking, 0.05), spec.weft.material,
                         "fabric");
  }
}

TEST_P(Yank, YarnEndNeitherOverloadsASegmentNorFlingsAVertex) {
  // The 0.3 m, 25-vertex cotton yarn hanging from its first vertex, settled 0.3 s; its free end
  // then pulled at 3 and 10 x its breaking force for 50 ms.
  const YarnSpec spec = hangingYarn();
  const double breaking = breakingForce(spec);
  for (const double multiple : {3.0, 10.0}) {
    SCOPED_TRACE(std::to_string(multiple) + " x the breaking force");
    Simulator sim(parameters(), {spec}, {});
    const int settle = static_cast<int>(std::lround(0.3 / GetParam().dt));
    for (int i = 0; i < settle; ++i) sim.step();
    const auto end = static_cast<std::uint32_t>(spec.num_vertices - 1);
    expectWithinStrength(yank(sim, end, multiple * breaking, breaking, 0.05), spec.material,
                         "yarn");
  }
}

INSTANTIATE_TEST_SUITE_P(Steps, Yank,
                         testing::Values(YankCase{1.0e-4, 96}, YankCase{1.0e-4, 192},
                                         YankCase{1.0e-4, 384}, YankCase{7.0e-5, 96},
                                         YankCase{1.0e-3, 96}, YankCase{5.0e-3, 96},
                                         YankCase{1.0e-2, 96}),
                         yankCaseName);

}  // namespace
}  // namespace yarn_tearing::test
