// A fabric built from its spec: counts, masses, rest lengths with crimp, indexing, pins, slits,
// and refusal of bad specs.
#include <gtest/gtest.h>

#include "fabric_support.hpp"

namespace yarn_tearing::test {
namespace {

FabricSpec crimpedPatch() {
  FabricSpec spec = cottonPatch(5, 4, 0.04, 0.03);
  spec.weft.radius = 2.0e-4;
  spec.warp_crimp = 0.08;
  spec.weft_crimp = 0.05;
  spec.origin = Eigen::Vector3d(1.0, 2.0, 3.0);
  return spec;
}

TEST(FabricConstruction, CountsMassesAndRestLengthsWithCrimp) {
  const FabricSpec spec = crimpedPatch();
  const Scene scene = buildScene({hangingYarn()}, {spec});
  ASSERT_EQ(scene.fabrics.size(), 1u);
  const Fabric& fabric = scene.fabrics[0];
  const int ends = spec.ends;
  const int picks = spec.picks;
  EXPECT_EQ(scene.vertices.size(), 25u + static_cast<std::size_t>(ends * picks));
  EXPECT_EQ(scene.edges.size(),
            24u + static_cast<std::size_t>(ends * (picks - 1) + picks * (ends - 1)));
  EXPECT_EQ(fabric.cells.size(), static_cast<std::size_t>((ends - 1) * (picks - 1)));
  ASSERT_EQ(scene.yarns.size(), 3u);
  EXPECT_EQ(scene.yarns[1].name, "cloth/warp");
  EXPECT_EQ(scene.yarns[2].name, "cloth/weft");
  EXPECT_EQ(scene.yarns[1].fabric, 0);
  EXPECT_EQ(scene.yarns[0].fabric, -1);
  EXPECT_EQ(scene.yarns[1].num_edges, static_cast<std::uint32_t>(ends * (picks - 1)));
  EXPECT_EQ(scene.yarns[2].num_edges, static_cast<std::uint32_t>(picks * (ends - 1)));

  // Rest length = spacing (1 + crimp); vertex spacing = size / (count - 1).
  const double warp_rest = 0.03 / (picks - 1) * 1.08;
  const double weft_rest = 0.04 / (ends - 1) * 1.05;
  double mass = 0.0;
  for (std::uint32_t v = fabric.first_vertex; v < scene.vertices.size(); ++v) {
    mass += scene.vertices.mass[v];
  }
  for (std::uint32_t e = scene.yarns[1].first_edge; e < scene.edges.size(); ++e) {
    const bool warp = scene.fabricSegmentOf(e).family == FabricFamily::kWarp;
    EXPECT_NEAR(scene.edges.original_rest_length[e], warp ? warp_rest : weft_rest, 1e-15);
    EXPECT_DOUBLE_EQ(scene.edges.area[e], warp ? spec.warp.area() : spec.weft.area());
  }
  // Total mass = rho A L over every yarn at its crimped length.
  const double expected = ends * spec.warp.linearDensity() * 0.03 * 1.08 +
                          picks * spec.weft.linearDensity() * 0.04 * 1.05;
  EXPECT_NEAR(mass, expected, 1e-12 * expected);
  // A corner carries half a warp and half a weft segment, an inner vertex two halves of each.
  EXPECT_NEAR(
      scene.vertices.mass[fabric.vertex(0, 0)],
      0.5 * spec.warp.linearDensity() * warp_rest + 0.5 * spec.weft.linearDensity() * weft_rest,
      1e-18);
  EXPECT_NEAR(scene.vertices.mass[fabric.vertex(1, 1)],
              spec.warp.linearDensity() * warp_rest + spec.weft.linearDensity() * weft_rest, 1e-18);

  // Positions: origin + row along the warp + column along the weft.
  const Eigen::Vector3d x = scene.vertices.position[scene.fabricVertex(0, 2, 3)];
  EXPECT_TRUE(x.isApprox(Eigen::Vector3d(1.0 + 3 * 0.01, 2.0, 3.0 - 2 * 0.01), 1e-12));
  EXPECT_EQ(scene.fabricVertex(0, -1, -1), fabric.vertex(3, 4));
  EXPECT_THROW(scene.fabricVertex(0, 4, 0), std::out_of_range);
  EXPECT_THROW(scene.fabricVertex(1, 0, 0), std::out_of_range);
}

TEST(FabricConstruction, SegmentsAreLabelledByFamilyYarnAndSegment) {
  const Scene scene = buildScene({}, {crimpedPatch()});
  const Fabric& fabric = scene.fabrics[0];
  for (FabricFamily family : {FabricFamily::kWarp, FabricFamily::kWeft}) {
    const std::uint32_t yarns = family == FabricFamily::kWarp ? fabric.ends : fabric.picks;
    for (std::uint32_t y = 0; y < yarns; ++y) {
      for (std::uint32_t s = 0; s < fabric.segmentsPerYarn(family); ++s) {
        const std::uint32_t e = scene.fabricEdge(0, {family, y, s});
        const FabricSegment back = scene.fabricSegmentOf(e);
        EXPECT_EQ(back.family, family);
        EXPECT_EQ(back.yarn, y);
        EXPECT_EQ(back.segment, s);
        EXPECT_EQ(scene.fabricOfEdge(e), 0);
        // Warp yarn y is column y, its segment s joins rows s and s + 1; weft the other way.
        const bool warp = family == FabricFamily::kWarp;
        EXPECT_EQ(scene.edges.vertex_a[e], warp ? fabric.vertex(s, y) : fabric.vertex(y, s));
        EXPECT_EQ(scene.edges.vertex_b[e],
                  warp ? fabric.vertex(s + 1, y) : fabric.vertex(y, s + 1));
      }
    }
  }
  EXPECT_THROW(scene.fabricEdge(0, {FabricFamily::kWarp, 5, 0}), std::out_of_range);
  EXPECT_THROW(scene.fabricEdge(0, {FabricFamily::kWeft, 0, 4}), std::out_of_range);
}

TEST(FabricConstruction, PinsSidesAndVerticesAndCutsSlits) {
  FabricSpec spec = crimpedPatch();
  spec.pinned_sides = {FabricSide::kLastColumn};
  spec.pinned = {{0, 0}, {-1, 1}};
  spec.slits = {{FabricFamily::kWeft, 1, 3, 2}};
  const Scene scene = buildScene({}, {spec});
  const Fabric& fabric = scene.fabrics[0];
  int pinned = 0;
  for (std::uint32_t r = 0; r < fabric.picks; ++r) {
    for (std::uint32_t c = 0; c < fabric.ends; ++c) {
      const bool expected = c == fabric.ends - 1 || (r == 0 && c == 0) || (r == 3 && c == 1);
      EXPECT_EQ(scene.vertices.motion[fabric.vertex(r, c)] == VertexMotion::kPinned, expected)
          << r << ", " << c;
      pinned += expected ? 1 : 0;
    }
  }
  EXPECT_EQ(pinned, 6);
  int broken = 0;
  for (std::size_t e = 0; e < scene.edges.size(); ++e) {
    if (scene.edges.intact(e)) continue;
    ++broken;
    const FabricSegment s = scene.fabricSegmentOf(e);
    EXPECT_EQ(s.family, FabricFamily::kWeft);
    EXPECT_EQ(s.segment, 2u);
    EXPECT_GE(s.yarn, 1u);
    EXPECT_LE(s.yarn, 3u);
  }
  EXPECT_EQ(broken, 3);
}

void expectRefused(const FabricSpec& spec, const std::string& field) {
  try {
    buildScene({}, {spec});
    ADD_FAILURE() << "accepted a spec with a bad " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cloth"), std::string::npos) << e.what();
  }
}

TEST(FabricConstruction, RefusesBadSpecsNamingTheField) {
  FabricSpec spec = crimpedPatch();
  spec.ends = 1;
  expectRefused(spec, "ends");
  spec = crimpedPatch();
  spec.warp_length = -1.0;
  expectRefused(spec, "warp_length");
  spec = crimpedPatch();
  spec.weft_direction = spec.warp_direction;
  expectRefused(spec, "parallel");
  spec = crimpedPatch();
  spec.weft.radius = 0.0;
  expectRefused(spec, "weft");
  spec = crimpedPatch();
  spec.warp_crimp = -0.1;
  expectRefused(spec, "warp_crimp");
  spec = crimpedPatch();
  spec.shear_rigidity = std::nan("");
  expectRefused(spec, "shear_rigidity");
  spec = crimpedPatch();
  spec.pinned = {{4, 0}};
  expectRefused(spec, "pinned");
  spec = crimpedPatch();
  spec.slits = {{FabricFamily::kWarp, 0, 5, 0}};
  expectRefused(spec, "slit");
  spec = crimpedPatch();
  spec.slits = {{FabricFamily::kWeft, 0, 0, 4}};
  expectRefused(spec, "slit segment");
  YarnSpec yarn = hangingYarn();
  yarn.name = "cloth";
  EXPECT_THROW(buildScene({yarn}, {crimpedPatch()}), std::invalid_argument);
}

}  // namespace
}  // namespace yarn_tearing::test
