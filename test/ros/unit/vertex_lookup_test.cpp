#include "yarn_tearing/ros/vertex_lookup.hpp"

#include <gtest/gtest.h>

#include "yarn_tearing/ros/input_rejected.hpp"
#include "yarn_tearing/ros/vertex_strength.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

/// A 5-vertex yarn "thread" (global vertices 0-4 or after the fabric's) and a fabric "cloth" of
/// 4 ends (columns) by 3 picks (rows).
Scene yarnAndFabric() {
  YarnSpec thread;
  thread.name = "thread";
  thread.num_vertices = 5;
  FabricSpec cloth;
  cloth.name = "cloth";
  cloth.ends = 4;
  cloth.picks = 3;
  return buildScene({thread}, {cloth});
}

VertexAddress byRowAndColumn(int row, int column) {
  VertexAddress address;
  address.by_row_and_column = true;
  address.row = row;
  address.column = column;
  return address;
}

VertexAddress byIndex(int vertex) {
  VertexAddress address;
  address.vertex = vertex;
  return address;
}

RefusalReason refusal(const Scene& scene, const std::string& name, const VertexAddress& address) {
  try {
    lookupVertex(scene, name, address);
  } catch (const InputRejected& e) {
    return e.reason();
  }
  return RefusalReason::kCount;
}

TEST(VertexLookup, AFabricVertexByRowAndColumnIsTheSameAsByIndex) {
  const Scene scene = yarnAndFabric();
  const Fabric& cloth = scene.fabrics.at(0);
  EXPECT_EQ(lookupVertex(scene, "cloth", byRowAndColumn(0, 0)), cloth.vertex(0, 0));
  EXPECT_EQ(lookupVertex(scene, "cloth", byRowAndColumn(2, 1)), cloth.vertex(2, 1));
  EXPECT_EQ(lookupVertex(scene, "cloth", byRowAndColumn(2, 1)),
            lookupVertex(scene, "cloth", byIndex(2 * 4 + 1)));
  // Negative row and column count from the last: the far corner.
  EXPECT_EQ(lookupVertex(scene, "cloth", byRowAndColumn(-1, -1)), cloth.vertex(2, 3));
  EXPECT_EQ(lookupVertex(scene, "cloth", byRowAndColumn(-1, -1)),
            lookupVertex(scene, "cloth", byIndex(-1)));
  EXPECT_EQ(lookupVertex(scene, "cloth", byRowAndColumn(-3, -4)), cloth.vertex(0, 0));
}

TEST(VertexLookup, RowsAndColumnsOutOfRangeAndRowsOfAYarnAreRefused) {
  const Scene scene = yarnAndFabric();
  EXPECT_EQ(refusal(scene, "cloth", byRowAndColumn(3, 0)), RefusalReason::kVertexOutOfRange);
  EXPECT_EQ(refusal(scene, "cloth", byRowAndColumn(-4, 0)), RefusalReason::kVertexOutOfRange);
  EXPECT_EQ(refusal(scene, "cloth", byRowAndColumn(0, 4)), RefusalReason::kVertexOutOfRange);
  EXPECT_EQ(refusal(scene, "cloth", byRowAndColumn(0, -5)), RefusalReason::kVertexOutOfRange);
  EXPECT_EQ(refusal(scene, "cloth", byIndex(12)), RefusalReason::kVertexOutOfRange);
  EXPECT_EQ(refusal(scene, "thread", byRowAndColumn(0, 0)), RefusalReason::kVertexOutOfRange);
  EXPECT_EQ(refusal(scene, "thread", byIndex(5)), RefusalReason::kVertexOutOfRange);
  EXPECT_EQ(refusal(scene, "rope", byIndex(0)), RefusalReason::kUnknownYarn);
  EXPECT_EQ(lookupVertex(scene, "thread", byIndex(-1)), scene.globalVertex(0, 4));
}

TEST(VertexLookup, TheRefusalNamesWhatIsAllowed) {
  const Scene scene = yarnAndFabric();
  try {
    lookupVertex(scene, "cloth", byRowAndColumn(0, 7));
    FAIL() << "column 7 of 4 accepted";
  } catch (const InputRejected& e) {
    EXPECT_EQ(std::string(e.what()), "column 7 of fabric 'cloth' out of range [-4, 3]");
  }
  EXPECT_EQ(byRowAndColumn(2, -1).describe(), "vertex (row 2, column -1)");
  EXPECT_EQ(byIndex(3).describe(), "vertex 3");
}

TEST(VertexBreakingForces, SumTheBreakingForcesOfTheEdgesAtEachVertex) {
  const Scene scene = yarnAndFabric();
  const std::vector<double> strength = vertexBreakingForces(scene);
  ASSERT_EQ(strength.size(), scene.vertices.position.size());
  // One edge's sigma_b pi r^2 (no scatter: strength factors 1).
  const double edge = scene.edges.area[0] * scene.yarns[0].material.curve.breakingStress();
  EXPECT_DOUBLE_EQ(strength[0], edge);        // the thread's end: one edge
  EXPECT_DOUBLE_EQ(strength[2], 2.0 * edge);  // inside the thread: two
  const std::uint32_t corner = 5;             // the fabric's vertex (0, 0): a warp and a weft
  const std::uint32_t inner = 5 + 1 * 4 + 1;  // (1, 1): two warp and two weft segments
  const double warp = scene.edges.area.back() *
                      scene.yarns[scene.edges.yarn.back()].material.curve.breakingStress();
  EXPECT_DOUBLE_EQ(strength[corner], 2.0 * warp);
  EXPECT_DOUBLE_EQ(strength[inner], 4.0 * warp);
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing
