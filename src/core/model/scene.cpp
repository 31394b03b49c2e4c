#include "yarn_tearing/core/model/scene.hpp"

#include <set>
#include <stdexcept>
#include <string>

#include "yarn_tearing/core/material/strength_scatter.hpp"
#include "yarn_tearing/core/model/fabric_builder.hpp"

namespace yarn_tearing {
namespace {

void addYarn(Scene& scene, const YarnSpec& spec) {
  const auto yarn_index = static_cast<std::uint32_t>(scene.yarns.size());
  Yarn yarn;
  yarn.name = spec.name;
  yarn.material = spec.material;
  yarn.radius = spec.effectiveRadius();
  yarn.first_vertex = static_cast<std::uint32_t>(scene.vertices.size());
  yarn.num_vertices = static_cast<std::uint32_t>(spec.num_vertices);
  yarn.first_edge = static_cast<std::uint32_t>(scene.edges.size());
  yarn.num_edges = yarn.num_vertices - 1;

  const int n = spec.num_vertices;
  const double segment = spec.length / (n - 1);
  const double segment_mass = spec.linearDensity() * segment;
  const Eigen::Vector3d step = spec.direction.normalized() * segment;
  for (int i = 0; i < n; ++i) {
    const bool end = (i == 0 || i == n - 1);
    const double share = end ? 0.5 : 1.0;
    const double extra = (i == n - 1) ? spec.end_mass : 0.0;
    scene.vertices.add(spec.start + step * i, share * segment_mass + extra, share * segment,
                       yarn_index);
  }
  const std::vector<double> strength =
      strengthFactors(spec.strength_scatter, std::vector<double>(yarn.num_edges, segment));
  for (std::uint32_t e = 0; e < yarn.num_edges; ++e) {
    scene.edges.add(yarn.first_vertex + e, yarn.first_vertex + e + 1, yarn_index, segment,
                    spec.area(), strength[e]);
  }
  scene.yarns.push_back(yarn);
  for (int p : spec.pinned) {
    scene.vertices.motion[scene.globalVertex(yarn_index, p)] = VertexMotion::kPinned;
  }
}

}  // namespace

int Scene::findYarn(const std::string& name) const {
  for (std::size_t i = 0; i < yarns.size(); ++i) {
    if (yarns[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::uint32_t Scene::globalVertex(std::size_t yarn, int local) const {
  if (yarn >= yarns.size()) throw std::out_of_range("no yarn " + std::to_string(yarn));
  const auto n = static_cast<int>(yarns[yarn].num_vertices);
  const int index = local < 0 ? n + local : local;
  if (index < 0 || index >= n) {
    throw std::out_of_range("vertex " + std::to_string(local) + " of yarn '" + yarns[yarn].name +
                            "' out of range [" + std::to_string(-n) + ", " + std::to_string(n - 1) +
                            "]");
  }
  return yarns[yarn].first_vertex + static_cast<std::uint32_t>(index);
}

int Scene::findFabric(const std::string& name) const {
  for (std::size_t i = 0; i < fabrics.size(); ++i) {
    if (fabrics[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::uint32_t Scene::fabricVertex(std::size_t fabric, int row, int column) const {
  if (fabric >= fabrics.size()) throw std::out_of_range("no fabric " + std::to_string(fabric));
  const Fabric& f = fabrics[fabric];
  const auto rows = static_cast<int>(f.picks);
  const auto columns = static_cast<int>(f.ends);
  const int r = row < 0 ? rows + row : row;
  const int c = column < 0 ? columns + column : column;
  if (r < 0 || r >= rows || c < 0 || c >= columns) {
    throw std::out_of_range("vertex (" + std::to_string(row) + ", " + std::to_string(column) +
                            ") of fabric '" + f.name + "' out of range: row in [" +
                            std::to_string(-rows) + ", " + std::to_string(rows - 1) +
                            "], column in [" + std::to_string(-columns) + ", " +
                            std::to_string(columns - 1) + "]");
  }
  return f.vertex(static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(c));
}

std::uint32_t Scene::fabricEdge(std::size_t fabric, const FabricSegment& segment) const {
  if (fabric >= fabrics.size()) throw std::out_of_range("no fabric " + std::to_string(fabric));
  const Fabric& f = fabrics[fabric];
  const std::uint32_t per_yarn = f.segmentsPerYarn(segment.family);
  const Yarn& group = yarns[f.group(segment.family)];
  if (segment.segment >= per_yarn || segment.yarn >= group.num_edges / per_yarn) {
    throw std::out_of_range(
        std::string(familyName(segment.family)) + " segment " + std::to_string(segment.segment) +
        " of yarn " + std::to_string(segment.yarn) + " of fabric '" + f.name + "' does not exist");
  }
  return group.first_edge + segment.yarn * per_yarn + segment.segment;
}

FabricSegment Scene::fabricSegmentOf(std::size_t edge) const {
  const Yarn& group = yarns[edges.yarn[edge]];
  const Fabric& f = fabrics.at(static_cast<std::size_t>(group.fabric));
  return f.segmentOf(group.family, static_cast<std::uint32_t>(edge) - group.first_edge);
}

Scene buildScene(const std::vector<YarnSpec>& specs, const std::vector<FabricSpec>& fabrics) {
  Scene scene;
  std::set<std::string> names;
  const auto claim = [&names](const std::string& name, const char* what) {
    if (!names.insert(name).second) {
      throw std::invalid_argument(std::string(what) +
                                  " names must be unique among yarns and "
                                  "fabrics (and their '<fabric>/warp', '<fabric>/weft'): '" +
                                  name + "' repeats");
    }
  };
  for (const YarnSpec& spec : specs) {
    spec.validate();
    claim(spec.name, "yarn");
    addYarn(scene, spec);
  }
  for (const FabricSpec& spec : fabrics) {
    spec.validate();
    claim(spec.name, "fabric");
    claim(spec.name + "/warp", "fabric");
    claim(spec.name + "/weft", "fabric");
    addFabric(scene, spec);
  }
  assignBreakingStrains(scene.yarns, scene.edges);
  return scene;
}

}  // namespace yarn_tearing
