#include "yarn_tearing/core/model/fabric_builder.hpp"

#include "yarn_tearing/core/material/strength_scatter.hpp"

namespace yarn_tearing {
namespace {

/// One family's segments: its rest length [m], mass [kg] and the scene yarn that groups them.
struct FamilyLayout {
  double rest_length = 0.0;
  double segment_mass = 0.0;
};

FamilyLayout layoutOf(const YarnSpec& yarn, double spacing, double crimp) {
  FamilyLayout layout;
  layout.rest_length = spacing * (1.0 + crimp);
  layout.segment_mass = yarn.linearDensity() * layout.rest_length;
  return layout;
}

/// Segments of one family meeting a vertex at index `i` of `count` along that family's yarn.
double segmentsAt(int i, int count) { return (i == 0 || i == count - 1) ? 1.0 : 2.0; }

Yarn groupOf(const Scene& scene, const FabricSpec& spec, FabricFamily family,
             std::uint32_t first_vertex, std::size_t fabric) {
  const YarnSpec& yarn = family == FabricFamily::kWarp ? spec.warp : spec.weft;
  Yarn group;
  group.name = spec.name + "/" + familyName(family);
  group.material = yarn.material;
  group.radius = yarn.effectiveRadius();
  group.first_vertex = first_vertex;
  group.num_vertices = static_cast<std::uint32_t>(spec.ends * spec.picks);
  group.first_edge = static_cast<std::uint32_t>(scene.edges.size());
  group.num_edges =
      static_cast<std::uint32_t>(spec.yarnCount(family) * spec.segmentsPerYarn(family));
  group.fabric = static_cast<std::int32_t>(fabric);
  group.family = family;
  return group;
}

void addFamilyEdges(Scene& scene, const FabricSpec& spec, const Fabric& fabric, FabricFamily family,
                    const FamilyLayout& layout) {
  const YarnSpec& yarn = family == FabricFamily::kWarp ? spec.warp : spec.weft;
  const Yarn& group = scene.yarns[fabric.group(family)];
  const std::vector<double> strength = strengthFactors(
      yarn.strength_scatter, std::vector<double>(group.num_edges, layout.rest_length));
  const auto yarns = static_cast<std::uint32_t>(spec.yarnCount(family));
  const std::uint32_t per_yarn = fabric.segmentsPerYarn(family);
  for (std::uint32_t y = 0; y < yarns; ++y) {
    for (std::uint32_t s = 0; s < per_yarn; ++s) {
      const bool warp = family == FabricFamily::kWarp;
      const std::uint32_t a = warp ? fabric.vertex(s, y) : fabric.vertex(y, s);
      const std::uint32_t b = warp ? fabric.vertex(s + 1, y) : fabric.vertex(y, s + 1);
      scene.edges.add(a, b, fabric.group(family), layout.rest_length, yarn.area(),
                      strength[y * per_yarn + s]);
    }
  }
}

void addCells(Scene& scene, std::size_t index) {
  Fabric& fabric = scene.fabrics[index];
  const std::vector<Eigen::Vector3d>& x = scene.vertices.position;
  for (std::uint32_t r = 0; r + 1 < fabric.picks; ++r) {
    for (std::uint32_t c = 0; c + 1 < fabric.ends; ++c) {
      FabricCell cell;
      cell.corner = {fabric.vertex(r, c), fabric.vertex(r, c + 1), fabric.vertex(r + 1, c),
                     fabric.vertex(r + 1, c + 1)};
      cell.edge = {scene.fabricEdge(index, {FabricFamily::kWeft, r, c}),
                   scene.fabricEdge(index, {FabricFamily::kWeft, r + 1, c}),
                   scene.fabricEdge(index, {FabricFamily::kWarp, c, r}),
                   scene.fabricEdge(index, {FabricFamily::kWarp, c + 1, r})};
      cell.diagonal_rest = {(x[cell.corner[3]] - x[cell.corner[0]]).norm(),
                            (x[cell.corner[2]] - x[cell.corner[1]]).norm()};
      fabric.cells.push_back(cell);
    }
  }
}

void pinSides(Scene& scene, const FabricSpec& spec, std::size_t fabric) {
  for (FabricSide side : spec.pinned_sides) {
    const bool row_side = side == FabricSide::kFirstRow || side == FabricSide::kLastRow;
    const int fixed = (side == FabricSide::kFirstRow || side == FabricSide::kFirstColumn) ? 0 : -1;
    const int count = row_side ? spec.ends : spec.picks;
    for (int i = 0; i < count; ++i) {
      const std::uint32_t v =
          row_side ? scene.fabricVertex(fabric, fixed, i) : scene.fabricVertex(fabric, i, fixed);
      scene.vertices.motion[v] = VertexMotion::kPinned;
    }
  }
  for (const FabricVertexIndex& p : spec.pinned) {
    scene.vertices.motion[scene.fabricVertex(fabric, p.row, p.column)] = VertexMotion::kPinned;
  }
}

void cutSlits(Scene& scene, const FabricSpec& spec, std::size_t fabric) {
  for (const FabricSlit& slit : spec.slits) {
    for (int y = slit.first_yarn; y <= slit.last_yarn; ++y) {
      const FabricSegment segment{slit.family, static_cast<std::uint32_t>(y),
                                  static_cast<std::uint32_t>(slit.segment)};
      scene.edges.broken[scene.fabricEdge(fabric, segment)] = 1;
    }
  }
}

}  // namespace

void addFabric(Scene& scene, const FabricSpec& spec) {
  const std::size_t index = scene.fabrics.size();
  Fabric fabric;
  fabric.name = spec.name;
  fabric.ends = static_cast<std::uint32_t>(spec.ends);
  fabric.picks = static_cast<std::uint32_t>(spec.picks);
  fabric.first_vertex = static_cast<std::uint32_t>(scene.vertices.size());
  fabric.shear_rigidity = spec.shear_rigidity;

  const Eigen::Vector3d row_step =
      spec.warp_direction.normalized() * (spec.warp_length / (spec.picks - 1));
  const Eigen::Vector3d column_step =
      spec.weft_direction.normalized() * (spec.weft_length / (spec.ends - 1));
  const FamilyLayout warp = layoutOf(spec.warp, row_step.norm(), spec.warp_crimp);
  const FamilyLayout weft = layoutOf(spec.weft, column_step.norm(), spec.weft_crimp);

  const Yarn warp_group = groupOf(scene, spec, FabricFamily::kWarp, fabric.first_vertex, index);
  fabric.warp_group = static_cast<std::uint32_t>(scene.yarns.size());
  for (int r = 0; r < spec.picks; ++r) {
    for (int c = 0; c < spec.ends; ++c) {
      const double warp_share = 0.5 * segmentsAt(r, spec.picks);
      const double weft_share = 0.5 * segmentsAt(c, spec.ends);
      const double mass = warp_share * warp.segment_mass + weft_share * weft.segment_mass;
      const double length = warp_share * warp.rest_length + weft_share * weft.rest_length;
      scene.vertices.add(spec.origin + r * row_step + c * column_step, mass, length,
                         fabric.warp_group);
    }
  }
  scene.yarns.push_back(warp_group);
  fabric.weft_group = fabric.warp_group + 1;
  scene.fabrics.push_back(fabric);
  addFamilyEdges(scene, spec, scene.fabrics[index], FabricFamily::kWarp, warp);
  scene.yarns.push_back(groupOf(scene, spec, FabricFamily::kWeft, fabric.first_vertex, index));
  addFamilyEdges(scene, spec, scene.fabrics[index], FabricFamily::kWeft, weft);
  addCells(scene, index);
  pinSides(scene, spec, index);
  cutSlits(scene, spec, index);
}

}  // namespace yarn_tearing
