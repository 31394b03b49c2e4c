#include "yarn_tearing/core/simulation/recoil_region.hpp"

#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include "yarn_tearing/core/model/edge_incidence.hpp"

namespace yarn_tearing {
namespace {

constexpr std::int64_t kOutside = -1;

/// Rest-length distance [m] of every vertex from the nearest end of a torn edge along intact
/// edges (infinite where the walk does not go): shortest paths that expand free vertices closer
/// than `reach` [m] only.
std::vector<double> walkFromTears(const Scene& scene, const std::vector<std::uint32_t>& torn,
                                  double reach) {
  const EdgeSet& edges = scene.edges;
  const VertexSet& vertices = scene.vertices;
  EdgeIncidence incidence;
  incidence.build(edges, vertices.size());
  std::vector<double> distance(vertices.size(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  for (std::uint32_t e : torn) {
    for (std::uint32_t v : {edges.vertex_a[e], edges.vertex_b[e]}) {
      distance[v] = 0.0;
      open.emplace(0.0, v);
    }
  }
  while (!open.empty()) {
    const auto [d, v] = open.top();
    open.pop();
    if (d > distance[v] || vertices.isSupport(v) || d >= reach) continue;
    for (const std::uint32_t* it = incidence.begin(v); it != incidence.end(v); ++it) {
      const std::uint32_t e = *it;
      if (!edges.intact(e)) continue;
      const std::uint32_t u = edges.vertex_a[e] == v ? edges.vertex_b[e] : edges.vertex_a[e];
      const double through = d + edges.original_rest_length[e];
      if (through < distance[u]) {
        distance[u] = through;
        open.emplace(through, u);
      }
    }
  }
  return distance;
}

void copyVertex(const VertexSet& from, std::size_t v, VertexSet& to) {
  to.position.push_back(from.position[v]);
  to.velocity.push_back(from.velocity[v]);
  to.mass.push_back(from.mass[v]);
  to.damping_length.push_back(from.damping_length[v]);
  to.motion.push_back(from.motion[v]);
  to.applied_force.push_back(from.applied_force[v]);
  to.kinematic_target.push_back(from.kinematic_target[v]);
  to.yarn.push_back(from.yarn[v]);
}

void copyEdge(const EdgeSet& from, std::size_t e, std::uint32_t a, std::uint32_t b, EdgeSet& to) {
  to.vertex_a.push_back(a);
  to.vertex_b.push_back(b);
  to.yarn.push_back(from.yarn[e]);
  to.original_rest_length.push_back(from.original_rest_length[e]);
  to.rest_length.push_back(from.rest_length[e]);
  to.area.push_back(from.area[e]);
  to.strength_factor.push_back(from.strength_factor[e]);
  to.breaking_strain.push_back(from.breaking_strain[e]);
  to.strain_limit.push_back(from.strain_limit[e]);
  to.plastic_strain.push_back(from.plastic_strain[e]);
  to.tension.push_back(from.tension[e]);
  to.spring_tension.push_back(from.spring_tension[e]);
  to.stress.push_back(from.stress[e]);
  to.strain.push_back(from.strain[e]);
  to.strain_rate.push_back(from.strain_rate[e]);
  to.loading_time.push_back(from.loading_time[e]);
  to.loading_start_strain.push_back(from.loading_start_strain[e]);
  to.rate_factor.push_back(from.rate_factor[e]);
  to.broken.push_back(from.broken[e]);
}

/// The state a step changes on edge `from_e` of `from`, copied to edge `to_e` of `to`.
void copyEdgeState(const EdgeSet& from, std::size_t from_e, EdgeSet& to, std::size_t to_e) {
  to.rest_length[to_e] = from.rest_length[from_e];
  to.strain_limit[to_e] = from.strain_limit[from_e];
  to.plastic_strain[to_e] = from.plastic_strain[from_e];
  to.tension[to_e] = from.tension[from_e];
  to.spring_tension[to_e] = from.spring_tension[from_e];
  to.stress[to_e] = from.stress[from_e];
  to.strain[to_e] = from.strain[from_e];
  to.strain_rate[to_e] = from.strain_rate[from_e];
  to.loading_time[to_e] = from.loading_time[from_e];
  to.loading_start_strain[to_e] = from.loading_start_strain[from_e];
  to.rate_factor[to_e] = from.rate_factor[from_e];
  to.broken[to_e] = from.broken[from_e];
}

}  // namespace

RecoilRegion RecoilRegion::around(const Scene& scene, const std::vector<std::uint32_t>& torn,
                                  double reach) {
  RecoilRegion region;
  const std::vector<double> distance = walkFromTears(scene, torn, reach);
  const VertexSet& vertices = scene.vertices;
  std::vector<std::uint8_t> own(vertices.size(), 0);
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (!(distance[v] < std::numeric_limits<double>::infinity())) continue;
    const bool boundary = !vertices.isSupport(v) && distance[v] >= reach;
    region.vertices.push_back(static_cast<std::uint32_t>(v));
    region.boundary.push_back(boundary ? 1 : 0);
    region.distance.push_back(distance[v]);
    own[v] = boundary ? 0 : 1;
  }
  const EdgeSet& edges = scene.edges;
  region.usable = true;
  for (std::uint32_t e : torn) region.usable = region.usable && scene.fabricOfEdge(e) < 0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e) || !(own[edges.vertex_a[e]] || own[edges.vertex_b[e]])) continue;
    region.edges.push_back(static_cast<std::uint32_t>(e));
    region.usable = region.usable && scene.fabricOfEdge(e) < 0;
  }
  region.usable = region.usable && !region.edges.empty();
  return region;
}

Scene RecoilRegion::subScene(const Scene& scene) const {
  Scene sub;
  sub.yarns = scene.yarns;
  for (Yarn& yarn : sub.yarns) yarn.fabric = -1;
  std::vector<std::int64_t> local(scene.vertices.size(), kOutside);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    local[vertices[i]] = static_cast<std::int64_t>(i);
    copyVertex(scene.vertices, vertices[i], sub.vertices);
  }
  for (std::uint32_t e : edges) {
    copyEdge(scene.edges, e, static_cast<std::uint32_t>(local[scene.edges.vertex_a[e]]),
             static_cast<std::uint32_t>(local[scene.edges.vertex_b[e]]), sub.edges);
  }
  return sub;
}

void RecoilRegion::writeBack(const Scene& sub, Scene& scene) const {
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (boundary[i]) continue;
    scene.vertices.position[vertices[i]] = sub.vertices.position[i];
    scene.vertices.velocity[vertices[i]] = sub.vertices.velocity[i];
  }
  for (std::size_t i = 0; i < edges.size(); ++i) copyEdgeState(sub.edges, i, scene.edges, edges[i]);
}

}  // namespace yarn_tearing
