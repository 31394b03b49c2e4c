#include "yarn_tearing/core/scene.hpp"

#include <set>
#include <stdexcept>
#include <string>

#include "yarn_tearing/core/strength_scatter.hpp"

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

Scene buildScene(const std::vector<YarnSpec>& specs) {
  Scene scene;
  std::set<std::string> names;
  for (const YarnSpec& spec : specs) {
    spec.validate();
    if (!names.insert(spec.name).second) {
      throw std::invalid_argument("yarn names must be unique: '" + spec.name + "' repeats");
    }
    addYarn(scene, spec);
  }
  assignBreakingStrains(scene.yarns, scene.edges);
  return scene;
}

}  // namespace yarn_tearing
