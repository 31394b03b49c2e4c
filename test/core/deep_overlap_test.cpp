// Solids placed through a yarn or a patch: a point half a segment inside an obstacle is refused
// where the obstacle is set or moved (it stays as it was, the scene keeps stepping at a normal
// step's cost); a touch, and an obstacle pressed in at a robot's speed, are taken by the contact
// and pushed out within the step.
#include "yarn_tearing/core/contact/deep_overlap.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "fabric_support.hpp"

namespace yarn_tearing::test {
namespace {

/// The deepest any free vertex lies inside `obstacle`, the yarn radius included [m].
double deepestFreeVertex(const Simulator& sim, const Obstacle& obstacle) {
  const Scene& scene = sim.scene();
  double deepest = -1.0;
  for (std::size_t v = 0; v < scene.vertices.size(); ++v) {
    if (scene.vertices.motion[v] != VertexMotion::kFree) continue;
    const double radius = scene.yarns[scene.vertices.yarn[v]].radius;
    deepest = std::max(deepest, radius - obstacle.signedDistance(scene.vertices.position[v]));
  }
  return deepest;
}

/// Steps `sim` `steps` times; each step converges and tears nothing.
void expectQuietSteps(Simulator& sim, int steps) {
  for (int i = 0; i < steps; ++i) {
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    ASSERT_EQ(sim.lastHealth().breaks, 0) << "step " << i;
  }
}

TEST(DeepOverlap, SolidsThroughAPatchAreRefusedNamingObstacleAndYarn) {
  Simulator sim = settledPatch();
  const Eigen::Vector3d middle = patchMiddle(sim.scene());
  Obstacle box;
  box.name = "box";
  box.shape = ObstacleShape::kBox;
  box.half_extents = Eigen::Vector3d::Constant(0.5);
  box.pose.translation() = middle;
  Obstacle plane;  // the solid z <= middle's height: the patch's lower half inside it
  plane.name = "plane";
  plane.pose.translation() = middle;
  for (const Obstacle& solid : {ball(middle, 0.015), box, ball(middle, 1.0e4), plane}) {
    try {
      sim.setObstacles({solid});
      ADD_FAILURE() << solid.name << " through the patch was taken";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("'" + solid.name + "'"), std::string::npos) << what;
      EXPECT_NE(what.find("'cloth"), std::string::npos) << what;
    }
    EXPECT_TRUE(sim.obstacles().empty()) << solid.name;
  }
  expectQuietSteps(sim, 20);
}

TEST(DeepOverlap, ATouchIsTakenAndPushedOutWithinTheStep) {
  Simulator sim = settledPatch();
  const double radius = 0.015;
  // Pressed 2 mm into the patch's middle from the front (+y), less than half a segment.
  const Obstacle touching =
      ball(patchMiddle(sim.scene()) + Eigen::Vector3d(0.0, radius - 2.0e-3, 0.0), radius);
  ASSERT_FALSE(findDeepOverlap(touching, sim.scene()));
  sim.setObstacles({touching});
  sim.step();
  EXPECT_TRUE(sim.lastHealth().projection_converged);
  EXPECT_EQ(sim.lastHealth().breaks, 0);
  EXPECT_LT(deepestFreeVertex(sim, touching), 1.0e-6);  // [m] out within the step
}

TEST(DeepOverlap, AJumpIntoAPatchIsRefusedAndAStrokeAtARobotsSpeedIsNot) {
  Simulator sim = settledPatch();
  const Eigen::Vector3d middle = patchMiddle(sim.scene());
  const double radius = 0.015;
  const Eigen::Vector3d start = middle + Eigen::Vector3d(0.0, radius + 2.0e-3, 0.0);
  sim.setObstacles({ball(start, radius)});
  Eigen::Isometry3d jump = Eigen::Isometry3d::Identity();
  jump.translation() = middle;
  EXPECT_THROW(sim.setObstaclePose(0, jump), std::invalid_argument);
  EXPECT_TRUE(sim.obstacles()[0].pose.translation().isApprox(start));
  // At 0.5 m/s towards the patch for 40 ms: it presses the patch 18 mm back.
  const double speed = 0.5;  // [m/s]
  Eigen::Isometry3d pose = sim.obstacles()[0].pose;
  for (int i = 0; i < 40; ++i) {
    pose.translation().y() -= speed * sim.parameters().time_step;
    ASSERT_NO_THROW(sim.setObstaclePose(0, pose)) << "step " << i;
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    ASSERT_LT(deepestFreeVertex(sim, sim.obstacles()[0]), 1.0e-6) << "step " << i;
  }
  EXPECT_EQ(sim.takeTearEvents().size(), 0u);
}

TEST(DeepOverlap, ABallThroughAYarnIsRefusedAndOneBesideItIsTaken) {
  Simulator sim(SimulationParameters{}, {hangingYarn()});
  const double segment = 0.3 / 24;
  // Around the middle vertex (at z = -0.15): its centre half a segment inside, and more.
  EXPECT_THROW(sim.setObstacles({ball(Eigen::Vector3d(0.0, 0.0, -0.15), 0.6 * segment)}),
               std::invalid_argument);
  // Beside it, 0.4 of a segment inside.
  const Obstacle beside = ball(Eigen::Vector3d(0.01 - 0.4 * segment, 0.0, -0.15), 0.01);
  ASSERT_NO_THROW(sim.setObstacles({beside}));
  expectQuietSteps(sim, 5);
  EXPECT_LT(deepestFreeVertex(sim, beside), 1.0e-6);
}

}  // namespace
}  // namespace yarn_tearing::test
