#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/ros/marker_builder.hpp"
#include "yarn_tearing/ros/materials_description.hpp"
#include "yarn_tearing/ros/message_conversion.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

/// Two yarns: "a" (4 vertices, pinned first) and "b" (3 vertices, pinned last).
std::vector<YarnSpec> twoYarns() {
  YarnSpec a;
  a.name = "a";
  a.num_vertices = 4;
  a.length = 0.3;
  a.pinned = {0};
  YarnSpec b = a;
  b.name = "b \"quoted\"";
  b.num_vertices = 3;
  b.start = Eigen::Vector3d(0.1, 0.0, 0.0);
  b.pinned = {-1};
  return {a, b};
}

TEST(YamlFloat, AlwaysReadsBackAsAFloat) {
  EXPECT_EQ(yamlFloat(1.0e-6), "1.0e-06");
  EXPECT_EQ(yamlFloat(3.0e8), "300000000.0");
  EXPECT_EQ(yamlFloat(3.0e20), "3.0e+20");
  EXPECT_EQ(yamlFloat(0.05), "0.05");
  EXPECT_EQ(yamlFloat(0.0), "0.0");
  EXPECT_EQ(yamlFloat(2.5e-9), "2.5e-09");
}

TEST(YamlQuoted, EscapesQuotesAndBackslashes) {
  EXPECT_EQ(yamlQuoted("a\"b\\c"), "\"a\\\"b\\\\c\"");
}

TEST(MaterialsDescription, DescribesEveryYarn) {
  const Simulator simulator(SimulationParameters{}, twoYarns());
  const std::string yaml = describeMaterialsYaml(simulator.scene());
  EXPECT_NE(yaml.find("\"a\":\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("\"b \\\"quoted\\\"\":\n"), std::string::npos) << yaml;
  const StressStrainCurve& curve = simulator.scene().yarns[0].material.curve;
  EXPECT_NE(yaml.find("breaking_stress: " + yamlFloat(curve.breakingStress())), std::string::npos);
  EXPECT_NE(yaml.find("youngs_modulus: " + yamlFloat(curve.youngsModulus())), std::string::npos);
  EXPECT_NE(yaml.find("curve: [[0.0, 0.0], "), std::string::npos) << yaml;
}

TEST(MaterialsDescription, WeakestBreakingForceFollowsTheStrengthScatter) {
  std::vector<YarnSpec> specs = twoYarns();
  const Simulator uniform(SimulationParameters{}, specs);
  const Yarn& a = uniform.scene().yarns[0];
  const double nominal = a.material.curve.breakingStress() * uniform.scene().edges.area[0];
  EXPECT_NEAR(weakestBreakingForce(uniform.scene(), a), nominal, 1.0e-12 * nominal);

  specs[0].num_vertices = 20;
  specs[0].strength_scatter.weibull_modulus = 10.0;
  const Simulator scattered(SimulationParameters{}, specs);
  const double weakest = weakestBreakingForce(scattered.scene(), scattered.scene().yarns[0]);
  // The weakest edge's strength sigma_b * f_e * A (scatter moves it either way from the nominal:
  // sigma_b is the mean at the gauge length).
  const std::vector<double>& f = scattered.scene().edges.strength_factor;
  const double smallest =
      *std::min_element(f.begin(), f.begin() + scattered.scene().yarns[0].num_edges);
  EXPECT_NEAR(weakest, nominal * smallest, 1.0e-12 * nominal);
  EXPECT_GT(std::abs(weakest - nominal), 1.0e-3 * nominal);
  EXPECT_NE(describeMaterialsYaml(scattered.scene())
                .find("weakest_breaking_force: " + yamlFloat(weakest) + "\n"),
            std::string::npos);
}

TEST(StressColor, RunsFromBlueToRed) {
  const auto expect_rgb = [](const std_msgs::ColorRGBA& c, float r, float g, float b) {
    EXPECT_FLOAT_EQ(c.r, r);
    EXPECT_FLOAT_EQ(c.g, g);
    EXPECT_FLOAT_EQ(c.b, b);
    EXPECT_FLOAT_EQ(c.a, 1.0F);
  };
  expect_rgb(stressColor(0.0), 0.0F, 0.0F, 1.0F);
  expect_rgb(stressColor(-3.0), 0.0F, 0.0F, 1.0F);
  expect_rgb(stressColor(0.5), 0.0F, 1.0F, 0.0F);
  expect_rgb(stressColor(1.0), 1.0F, 0.0F, 0.0F);
  expect_rgb(stressColor(7.0), 1.0F, 0.0F, 0.0F);
}

TEST(MarkerBuilder, StableIdsAndOneDeleteAllOnly) {
  const Simulator simulator(SimulationParameters{}, twoYarns());
  MarkerBuilder builder("world", 0.002);
  const auto first = builder.build(simulator.scene(), ros::Time(1.0));
  ASSERT_EQ(first.markers.size(), 9U);
  EXPECT_EQ(first.markers[0].action, visualization_msgs::Marker::DELETEALL);
  const auto second = builder.build(simulator.scene(), ros::Time(2.0));
  ASSERT_EQ(second.markers.size(), 8U);
  for (std::size_t y = 0; y < 2; ++y) {  // the yarns' names, after the other markers
    const visualization_msgs::Marker& label = second.markers[6 + y];
    EXPECT_EQ(label.type, visualization_msgs::Marker::TEXT_VIEW_FACING);
    EXPECT_EQ(label.action, visualization_msgs::Marker::ADD);
    EXPECT_EQ(label.text, simulator.scene().yarns[y].name);
    EXPECT_EQ(label.ns, label.text);
    EXPECT_EQ(label.id, 3);
    EXPECT_GT(label.pose.position.z,
              simulator.scene().vertices.position[simulator.scene().yarns[y].first_vertex].z());
  }
  for (std::size_t i = 0; i < 6; ++i) {
    const visualization_msgs::Marker& m = second.markers[i];
    EXPECT_EQ(m.ns, simulator.scene().yarns[i / 3].name);
    EXPECT_EQ(m.id, static_cast<int>(i % 3));
    EXPECT_EQ(m.header.frame_id, "world");
    EXPECT_DOUBLE_EQ(m.pose.orientation.w, 1.0);
    EXPECT_EQ(m.action,
              i % 3 == 2 ? visualization_msgs::Marker::DELETE : visualization_msgs::Marker::ADD);
  }
  EXPECT_EQ(second.markers[0].type, visualization_msgs::Marker::LINE_LIST);
  EXPECT_EQ(second.markers[0].points.size(), 6U);  // 3 segments
  EXPECT_EQ(second.markers[0].colors.size(), 6U);
  EXPECT_EQ(second.markers[1].type, visualization_msgs::Marker::SPHERE_LIST);
  EXPECT_EQ(second.markers[1].points.size(), 4U);

  builder.addBreak(1, Eigen::Vector3d(0.1, 0.0, -0.1));
  const auto torn = builder.build(simulator.scene(), ros::Time(3.0));
  EXPECT_EQ(torn.markers[5].action, visualization_msgs::Marker::ADD);
  EXPECT_EQ(torn.markers[5].type, visualization_msgs::Marker::CUBE_LIST);
  ASSERT_EQ(torn.markers[5].points.size(), 1U);
  EXPECT_DOUBLE_EQ(torn.markers[5].points[0].z, -0.1);
  builder.clearBreaks();
  EXPECT_EQ(builder.build(simulator.scene(), ros::Time(4.0)).markers[5].action,
            visualization_msgs::Marker::DELETE);
}

/// The fabric's shaded faces (its TRIANGLE_LIST marker) among a scene's markers.
visualization_msgs::Marker fabricMesh(const Simulator& simulator) {
  MarkerBuilder builder("world", 1.0e-3);
  for (const visualization_msgs::Marker& marker :
       builder.build(simulator.scene(), ros::Time(1.0)).markers) {
    if (marker.type == visualization_msgs::Marker::TRIANGLE_LIST) return marker;
  }
  ADD_FAILURE() << "no TRIANGLE_LIST marker";
  return {};
}

TEST(MarkerBuilder, FabricMeshLooksTheSameFromEitherSide) {
  FabricSpec fabric;
  fabric.name = "patch";
  fabric.ends = 3;
  fabric.picks = 3;
  const visualization_msgs::Marker front =
      fabricMesh(Simulator(SimulationParameters{}, {}, {fabric}));
  ASSERT_EQ(front.points.size(), 2U * 2U * 6U);  // 2 x 2 cells, two triangles each
  // One colour per point: RViz then draws the triangles unlit, the same from both sides.
  ASSERT_EQ(front.colors.size(), front.points.size());
  for (const std_msgs::ColorRGBA& color : front.colors) {
    EXPECT_GT(color.r, 0.3F);
    EXPECT_LE(color.r, 1.0F);
    EXPECT_EQ(color.a, 1.0F);
  }
  // The same patch turned over (its weft reversed, so every triangle's normal too) is shaded alike.
  FabricSpec flipped = fabric;
  flipped.origin = fabric.origin + fabric.weft_length * fabric.weft_direction;
  flipped.weft_direction = -fabric.weft_direction;
  const visualization_msgs::Marker back =
      fabricMesh(Simulator(SimulationParameters{}, {}, {flipped}));
  ASSERT_EQ(back.colors.size(), front.colors.size());
  for (std::size_t i = 0; i < front.colors.size(); ++i) {
    EXPECT_FLOAT_EQ(back.colors[i].r, front.colors[i].r) << "point " << i;
  }
}

TEST(MessageConversion, UsesPerYarnLocalIndices) {
  Simulator simulator(SimulationParameters{}, twoYarns());
  simulator.step();
  const YarnStateArray states = toYarnStateArray(simulator, "world", ros::Time(1.8e9));
  EXPECT_EQ(states.header.frame_id, "world");
  EXPECT_DOUBLE_EQ(states.header.stamp.toSec(), 1.8e9);
  EXPECT_DOUBLE_EQ(states.sim_time, simulator.time());
  ASSERT_EQ(states.yarns.size(), 2U);
  const YarnState& b = states.yarns[1];
  EXPECT_EQ(b.positions.size(), 3U);
  EXPECT_EQ(b.velocities.size(), 3U);
  EXPECT_EQ(b.edge_vertices, (std::vector<std::int32_t>{0, 1, 1, 2}));
  for (const auto* field : {&b.rest_lengths, &b.tensions, &b.stresses, &b.strains,
                            &b.plastic_strains, &b.strain_limits}) {
    EXPECT_EQ(field->size(), 2U);
  }
  EXPECT_EQ(b.broken.size(), 2U);
  EXPECT_EQ(b.support_vertices, (std::vector<std::int32_t>{2}));
  ASSERT_EQ(b.support_forces.size(), 1U);
  EXPECT_LT(b.support_forces[0].z, 0.0);  // the hanging weight pulls the holder down
  EXPECT_DOUBLE_EQ(b.positions[0].x, 0.1);
  EXPECT_EQ(states.yarns[0].support_vertices, (std::vector<std::int32_t>{0}));
}

TEST(MessageConversion, BreakEventNamesTheYarn) {
  const Simulator simulator(SimulationParameters{}, twoYarns());
  TearEvent event;
  event.yarn = 1;
  event.edge = 1;
  event.vertex_a = 1;
  event.vertex_b = 2;
  event.position = Eigen::Vector3d(0.1, 0.0, -0.2);
  event.time = 2.5;
  event.tension = 9.4;
  const BreakEvent msg = toBreakEventMsg(event, simulator.scene(), "world", ros::Time(1.8e9));
  EXPECT_EQ(msg.yarn, simulator.scene().yarns[1].name);
  EXPECT_EQ(msg.header.frame_id, "world");
  EXPECT_DOUBLE_EQ(msg.header.stamp.toSec(), 1.8e9);
  EXPECT_DOUBLE_EQ(msg.sim_time, 2.5);
  EXPECT_EQ(msg.edge, 1);
  EXPECT_EQ(msg.vertex_b, 2);
  EXPECT_DOUBLE_EQ(msg.position.z, -0.2);
  EXPECT_DOUBLE_EQ(msg.tension, 9.4);
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
