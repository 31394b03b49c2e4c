#include "yarn_tearing/core/simulation/release_run.hpp"

#include <algorithm>

namespace yarn_tearing {
namespace {

/// The one other intact edge of edge e's yarn at vertex v, or -1 where none or several meet.
std::int64_t nextAlongYarn(const EdgeSet& edges, const EdgeIncidence& incidence, std::uint32_t v,
                           std::uint32_t e) {
  std::int64_t next = -1;
  for (const std::uint32_t* it = incidence.begin(v); it != incidence.end(v); ++it) {
    const std::uint32_t f = *it;
    if (f == e || !edges.intact(f) || edges.yarn[f] != edges.yarn[e]) continue;
    if (next >= 0) return -1;
    next = f;
  }
  return next;
}

/// The far end of edge e from vertex v.
std::uint32_t otherEnd(const EdgeSet& edges, std::uint32_t e, std::uint32_t v) {
  return edges.vertex_a[e] == v ? edges.vertex_b[e] : edges.vertex_a[e];
}

/// Rest length [m] of the run from torn edge `torn` on through its end `v`, over the edges
/// carrying at least `threshold` [N].
double runLength(const EdgeSet& edges, const EdgeIncidence& incidence, std::uint32_t torn,
                 std::uint32_t v, double threshold) {
  double length = 0.0;
  std::int64_t next = nextAlongYarn(edges, incidence, v, torn);
  // A run is at most the yarn's edge count long; the bound keeps a ring from looping.
  for (std::size_t walked = 0; next >= 0 && walked < edges.size(); ++walked) {
    const auto e = static_cast<std::uint32_t>(next);
    if (edges.tension[e] < threshold) break;
    length += edges.original_rest_length[e];
    v = otherEnd(edges, e, v);
    next = nextAlongYarn(edges, incidence, v, e);
  }
  return length;
}

}  // namespace

double releaseCrossingTime(const Scene& scene, const EdgeIncidence& incidence,
                           const std::vector<std::uint32_t>& torn) {
  const EdgeSet& edges = scene.edges;
  double longest = 0.0;
  for (std::uint32_t e : torn) {
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    double peak = 0.0;  // the more loaded neighbour's tension [N]
    for (std::uint32_t v : {a, b}) {
      const std::int64_t next = nextAlongYarn(edges, incidence, v, e);
      if (next >= 0) peak = std::max(peak, edges.tension[static_cast<std::size_t>(next)]);
    }
    if (!(peak > 0.0)) continue;
    const double run = std::max(runLength(edges, incidence, e, a, 0.5 * peak),
                                runLength(edges, incidence, e, b, 0.5 * peak));
    longest = std::max(longest, run / scene.yarns[edges.yarn[e]].material.waveSpeed());
  }
  return longest;
}

}  // namespace yarn_tearing
