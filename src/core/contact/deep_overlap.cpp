#include "yarn_tearing/core/contact/deep_overlap.hpp"

#include <cmath>
#include <cstdio>

#include "yarn_tearing/core/contact/edge_rounding.hpp"

namespace yarn_tearing {
namespace {

bool isFree(const VertexSet& vertices, std::uint32_t v) {
  return vertices.motion[v] == VertexMotion::kFree;
}

/// How far a yarn of radius `radius` [m] centred at `p` lies inside `obstacle` [m] (negative
/// when clear of it).
double depthAt(const Obstacle& obstacle, const Eigen::Vector3d& p, double radius, double rounding) {
  return radius - obstacle.signedDistance(p, rounding);
}

/// Keeps the deeper of `best` and the point of edge `e` at depth `depth` [m] beside `vertex`.
void keepDeeper(std::uint32_t e, std::uint32_t vertex, double depth, double allowed,
                std::optional<DeepOverlap>& best) {
  if (depth <= allowed) return;
  if (best && depth - allowed <= best->depth - best->allowed) return;
  best = DeepOverlap{e, vertex, depth, allowed};
}

}  // namespace

std::optional<DeepOverlap> findDeepOverlap(const Obstacle& obstacle, const Scene& scene) {
  const VertexSet& vertices = scene.vertices;
  const EdgeSet& edges = scene.edges;
  const double bound = obstacle.boundingRadius();
  const Eigen::Vector3d center = obstacle.pose.translation();
  std::optional<DeepOverlap> best;
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    if (!isFree(vertices, a) && !isFree(vertices, b)) continue;
    const Eigen::Vector3d& xa = vertices.position[a];
    const Eigen::Vector3d& xb = vertices.position[b];
    const double radius = scene.yarns[edges.yarn[e]].radius;
    const double half = 0.5 * (xa - xb).norm();
    if (std::isfinite(bound) && (0.5 * (xa + xb) - center).norm() > bound + half + radius) {
      continue;  // clear of the solid's bounding ball
    }
    const double allowed = kAllowedOverlapFraction * edges.rest_length[e];
    const double rounding = contactRounding(obstacle, radius, edges.rest_length[e]);
    if (edges.intact(e)) {
      const double t = obstacle.closestOnSegment(xa, xb, rounding);
      const Eigen::Vector3d p = (1.0 - t) * xa + t * xb;
      keepDeeper(e, t < 0.5 ? a : b, depthAt(obstacle, p, radius, rounding), allowed, best);
      continue;
    }
    for (const std::uint32_t v : {a, b}) {  // a torn segment's loose ends
      if (isFree(vertices, v)) {
        keepDeeper(e, v, depthAt(obstacle, vertices.position[v], radius, rounding), allowed, best);
      }
    }
  }
  return best;
}

std::string describeDeepOverlap(const DeepOverlap& overlap, const Obstacle& obstacle,
                                const Scene& scene) {
  const std::string& yarn = scene.yarns[scene.edges.yarn[overlap.edge]].name;
  char text[160];
  std::snprintf(text, sizeof(text), "%.3g mm deep at edge %u (vertex %u), more than the %.3g mm",
                overlap.depth * 1e3, overlap.edge, overlap.vertex, overlap.allowed * 1e3);
  return "obstacle '" + obstacle.name + "' lies through yarn '" + yarn + "': " + text +
         " (half a segment) that one step's contact pushes out; place it outside the yarns";
}

}  // namespace yarn_tearing
