// The step after a tear in a fabric whose release unloads the torn yarn's loaded run within two
// recoil substeps is taken whole. The loaded run is checked against a taut yarn's (all of it)
// and a wide trouser tear's (shortened by the crossing yarns), and the whole steps against the
// same tears with their recoil substepped.
#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "fabric_support.hpp"
#include "yarn_tearing/core/model/edge_incidence.hpp"
#include "yarn_tearing/core/simulation/release_run.hpp"

namespace yarn_tearing::test {
namespace {

/// The loaded run [m] of the yarn torn at `edge`: releaseCrossingTime() times c.
double loadedRun(const Scene& scene, std::uint32_t edge) {
  EdgeIncidence incidence;
  incidence.build(scene.edges, scene.vertices.size());
  return releaseCrossingTime(scene, incidence, {edge}) *
         scene.yarns[scene.edges.yarn[edge]].material.waveSpeed();
}

/// A cotton weave of `ends` warp yarns by 16 picks, 2 mm between yarns, its first row held, with
/// a slit along its middle over a quarter of the picks; the two halves of the first row are drawn
/// apart along the weft at 0.1 m/s each (16 ends: the scene of BM_FabricTearing/16).
class TrouserTip {
 public:
  static constexpr int kPicks = 16;
  static constexpr double kSpacing = 0.002;  ///< [m]

  TrouserTip(const SimulationParameters& parameters, int ends)
      : ends_(ends), sim_(parameters, {}, {spec(ends)}), time_step_(parameters.time_step) {
    const Scene& scene = sim_.scene();
    for (int c = 0; c < ends_; ++c) {
      origin_.push_back(scene.vertices.position[scene.fabricVertex(0, -1, c)]);
    }
  }
  static FabricSpec spec(int ends) {
    FabricSpec spec = cottonPatch(ends, kPicks, kSpacing * (ends - 1), kSpacing * (kPicks - 1));
    spec.slits = {{FabricFamily::kWeft, kPicks - kPicks / 4, kPicks - 1, ends / 2 - 1}};
    return spec;
  }
  /// One step with the grips moved on.
  void step() {
    const double travel = 0.1 * (sim_.time() + time_step_);
    for (int c = 0; c < ends_; ++c) {
      const double sign = c < ends_ / 2 ? -1.0 : 1.0;
      sim_.setKinematicTarget(sim_.scene().fabricVertex(0, -1, c),
                              origin_[c] + Eigen::Vector3d(sign * travel, 0.0, 0.0));
    }
    sim_.step();
  }
  Simulator& sim() { return sim_; }

 private:
  int ends_;
  Simulator sim_;
  double time_step_;  ///< [s]
  std::vector<Eigen::Vector3d> origin_;
};

/// A taut yarn torn anywhere unloads along all of each piece: its run is the longer piece's rest
/// length.
TEST(FabricTipRecoil, ATautYarnsLoadedRunIsItsLongerPiece) {
  const int vertices = 101;
  const std::uint32_t weak = 30;
  Simulator sim(parametersWithoutGravity(), weakEdgeYarnScene(vertices, weak, 0.2));
  const std::uint32_t drawn = sim.scene().globalVertex(0, -1);
  while (!sim.recoilPending() && sim.time() < 1.0) {
    const Eigen::Vector3d x = sim.scene().vertices.position[drawn];
    sim.setKinematicTarget(drawn, x + Eigen::Vector3d(2.0e-4, 0.0, 0.0));
    sim.step();
  }
  const std::vector<TearEvent> events = sim.takeTearEvents();
  ASSERT_EQ(events.size(), 1u);
  ASSERT_EQ(events[0].edge, weak);
  const double longer = 0.0125 * static_cast<double>(vertices - 2 - weak);  // [m]
  EXPECT_NEAR(loadedRun(sim.scene(), weak), longer, 1e-9 * longer);
}

/// At the tip of a trouser tear 48 ends wide the crossing yarns take the torn weft's load before
/// its ends: its run stops short of the 23 cells on its longer side.
TEST(FabricTipRecoil, TheCrossingYarnsShortenATearTipsLoadedRun) {
  TrouserTip trouser({}, 48);
  while (!trouser.sim().recoilPending() && trouser.sim().time() < 0.2) trouser.step();
  const std::vector<TearEvent> events = trouser.sim().takeTearEvents();
  ASSERT_EQ(events.size(), 1u);
  const double cells = loadedRun(trouser.sim().scene(), events[0].edge) / TrouserTip::kSpacing;
  std::cout << "loaded run at the tip: " << cells << " of 23 cells\n";
  EXPECT_GE(cells, 1.0);
  EXPECT_LT(cells, 23.0);
}

/// Over 50 steps from the trouser tear's first tear (ten tears, one every five or six steps),
/// the steps after its tip tears, taken whole, tear the same segments at the same times as the
/// same steps taken in recoil substeps (substep_every_recoil), none past its breaking force.
TEST(FabricTipRecoil, WholeStepsAfterTipTearsTearAsTheSubstepsDo) {
  SimulationParameters substepped;
  substepped.substep_every_recoil = true;
  TrouserTip whole({}, 16);
  TrouserTip compared(substepped, 16);
  const double breaking = breakingForce(TrouserTip::spec(16).weft);
  std::vector<TearEvent> whole_events;
  std::vector<TearEvent> compared_events;
  int first = -1;  // the step of the first tear
  for (int i = 0; i < 300 && (first < 0 || i < first + 50); ++i) {
    const bool pending = whole.sim().recoilPending();
    whole.step();
    compared.step();
    if (pending) {
      EXPECT_EQ(whole.sim().lastHealth().substeps, 1) << "step " << i;
      EXPECT_GT(compared.sim().lastHealth().substeps, 1) << "step " << i;
    }
    for (const TearEvent& e : whole.sim().takeTearEvents()) whole_events.push_back(e);
    for (const TearEvent& e : compared.sim().takeTearEvents()) compared_events.push_back(e);
    if (first < 0 && !whole_events.empty()) first = i;
  }
  ASSERT_GE(whole_events.size(), 8u);
  ASSERT_EQ(whole_events.size(), compared_events.size());
  for (std::size_t i = 0; i < whole_events.size(); ++i) {
    EXPECT_EQ(whole_events[i].edge, compared_events[i].edge);
    EXPECT_DOUBLE_EQ(whole_events[i].time, compared_events[i].time);
    EXPECT_LE(whole_events[i].tension, breaking * (1.0 + 1e-9));
    EXPECT_LE(compared_events[i].tension, breaking * (1.0 + 1e-9));
  }
}

}  // namespace
}  // namespace yarn_tearing::test
