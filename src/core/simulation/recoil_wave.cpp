#include "yarn_tearing/core/simulation/recoil_wave.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "yarn_tearing/core/forces/explicit_forces.hpp"

namespace yarn_tearing {
namespace {

/// The substep as a fraction of the explicit stability limit 2 / omega_max [-]. On a uniform
/// chain omega_max = 2 c / L, so this is the Courant number c h / L: near 1 the discrete chain
/// carries a step in strain with little dispersion.
constexpr double kCourant = 0.97;

/// Relative slack [-] within which an edge counts as held at its breaking length: the stop
/// holds it there to the projection's tolerance.
constexpr double kStopSlack = 1.0 + 1.0e-6;

constexpr double kNever = std::numeric_limits<double>::infinity();

/// The springs' stiffness k = E A f / L0 [N/m] per edge (0 for torn edges).
std::vector<double> springStiffness(const Scene& scene) {
  const EdgeSet& edges = scene.edges;
  std::vector<double> k(edges.size(), 0.0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e)) continue;
    const double modulus = scene.yarns[edges.yarn[e]].material.curve.youngsModulus();
    k[e] = modulus * edges.area[e] * edges.rate_factor[e] / edges.original_rest_length[e];
  }
  return k;
}

/// The largest stable substep [s]: 2 / omega_max, omega_max^2 bounded per free vertex by
/// Gershgorin's circle, 2 sum k / m over its edges.
double stableSubstep(const Scene& scene, const std::vector<double>& k) {
  const EdgeSet& edges = scene.edges;
  const VertexSet& vertices = scene.vertices;
  std::vector<double> stiffness(vertices.size(), 0.0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    stiffness[edges.vertex_a[e]] += k[e];
    stiffness[edges.vertex_b[e]] += k[e];
  }
  double omega2 = 0.0;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (!vertices.isSupport(v)) omega2 = std::max(omega2, 2.0 * stiffness[v] / vertices.mass[v]);
  }
  return omega2 > 0.0 ? 2.0 / std::sqrt(omega2) : kNever;
}

/// Each edge's breaking length L0 (1 + eps_b) [m].
std::vector<double> breakingLengths(const EdgeSet& edges) {
  std::vector<double> length(edges.size(), 0.0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    length[e] = edges.original_rest_length[e] * (1.0 + edges.breaking_strain[e]);
  }
  return length;
}

/// The intact edges that begin the step held at their breaking length by the stop past it
/// (within kStopSlack): they were not the edge their piece tore, and the stop holds them until
/// the wave unloads them.
std::vector<std::uint32_t> edgesAtStop(const EdgeSet& edges,
                                       const std::vector<double>& breaking_length,
                                       const std::vector<Eigen::Vector3d>& x) {
  std::vector<std::uint32_t> stops;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e)) continue;
    const double length = (x[edges.vertex_b[e]] - x[edges.vertex_a[e]]).norm();
    if (length * kStopSlack >= breaking_length[e]) stops.push_back(static_cast<std::uint32_t>(e));
  }
  return stops;
}

/// Tension [N] of a tension-only spring of stiffness `k` [N/m] and rest length `rest` [m] at
/// `length` [m].
double springTension(double k, double rest, double length) {
  const double stretch = length - rest;
  return stretch > 0.0 ? k * stretch : 0.0;
}

/// The explicit integration's state: which vertices it moves, where the others are.
class WaveState {
 public:
  WaveState(const VertexSet& vertices, const std::vector<Eigen::Vector3d>& start_acceleration,
            double duration)
      : vertices_(vertices),
        start_position_(vertices.position),
        start_velocity_(vertices.velocity),
        start_acceleration_(start_acceleration),
        moving_(vertices.size(), 0),
        duration_(duration) {}

  bool moving(std::size_t v) const { return moving_[v] != 0; }
  /// Lets free vertex v move from time t [s] on, from where its path has it.
  void startMoving(std::size_t v, double t, VertexSet& vertices) {
    vertices.position[v] = pathPosition(v, t);
    vertices.velocity[v] = pathVelocity(v, t);
    moving_[v] = 1;
  }
  /// Vertex v's position at time t [s]: the integrated one while it moves, else its path's.
  Eigen::Vector3d position(std::size_t v, double t) const {
    return moving_[v] ? vertices_.position[v] : pathPosition(v, t);
  }
  /// Puts every vertex that did not move where its path ends, with its path's velocity.
  void finish(VertexSet& vertices) const {
    for (std::size_t v = 0; v < vertices.size(); ++v) {
      if (moving_[v]) continue;
      vertices.position[v] = pathPosition(v, duration_);
      vertices.velocity[v] = pathVelocity(v, duration_);
    }
  }

 private:
  /// Pinned in place, kinematic linearly to its target, free on as it moved [m].
  Eigen::Vector3d pathPosition(std::size_t v, double t) const {
    switch (vertices_.motion[v]) {
      case VertexMotion::kPinned:
        return start_position_[v];
      case VertexMotion::kKinematic:
        return start_position_[v] +
               (t / duration_) * (vertices_.kinematic_target[v] - start_position_[v]);
      case VertexMotion::kFree:
        break;
    }
    return start_position_[v] + t * start_velocity_[v] + (0.5 * t * t) * start_acceleration_[v];
  }
  Eigen::Vector3d pathVelocity(std::size_t v, double t) const {
    switch (vertices_.motion[v]) {
      case VertexMotion::kPinned:
        return Eigen::Vector3d::Zero();
      case VertexMotion::kKinematic:
        return (vertices_.kinematic_target[v] - start_position_[v]) / duration_;
      case VertexMotion::kFree:
        break;
    }
    return start_velocity_[v] + t * start_acceleration_[v];
  }

  const VertexSet& vertices_;
  std::vector<Eigen::Vector3d> start_position_;             ///< [m]
  std::vector<Eigen::Vector3d> start_velocity_;             ///< [m/s]
  const std::vector<Eigen::Vector3d>& start_acceleration_;  ///< [m/s^2]
  std::vector<std::uint8_t> moving_;
  double duration_;  ///< [s]
};

/// Indices 0..time.size()-1 with a finite time, in increasing time.
std::vector<std::uint32_t> inOrderOf(const std::vector<double>& time) {
  std::vector<std::uint32_t> order;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < kNever) order.push_back(static_cast<std::uint32_t>(i));
  }
  std::stable_sort(order.begin(), order.end(),
                   [&time](std::uint32_t i, std::uint32_t j) { return time[i] < time[j]; });
  return order;
}

/// The region's edges as the wave's springs, and the forces that do not depend on them.
struct Springs {
  std::vector<double> k;                ///< stiffness E A f / L0 per edge (0: torn) [N/m]
  std::vector<double> breaking_length;  ///< L0 (1 + eps_b) per edge [m]
  std::vector<std::uint32_t> stops;     ///< edges held at their breaking length at the start
  std::vector<double> tear_length;      ///< length at which an edge tears in the wave [m]
  // accumulateExternalForces() split for the substeps' loop: what stays over the step, and what
  // follows the velocity.
  std::vector<Eigen::Vector3d> steady_force;  ///< gravity and applied force per vertex [N]
  std::vector<double> drag;                   ///< air damping per vertex [N s/m]
};

Springs springsOf(const Scene& scene, const SimulationParameters& parameters) {
  const VertexSet& vertices = scene.vertices;
  Springs springs;
  springs.k = springStiffness(scene);
  springs.breaking_length = breakingLengths(scene.edges);
  springs.stops = edgesAtStop(scene.edges, springs.breaking_length, vertices.position);
  // An edge drawn to its breaking length within the wave tears: the step is taken otherwise.
  springs.tear_length = springs.breaking_length;
  for (std::uint32_t e : springs.stops) springs.tear_length[e] = kNever;
  springs.steady_force.resize(vertices.size());
  springs.drag.resize(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    springs.steady_force[v] = vertices.mass[v] * parameters.gravity + vertices.applied_force[v];
    springs.drag[v] = parameters.air_damping * vertices.damping_length[v];
  }
  return springs;
}

/// When the wave sets each free vertex moving and each edge pulling (from its first free
/// end's arrival), in that order.
struct WaveSchedule {
  std::vector<double> vertex_arrival;   ///< per vertex [s]; infinite for held ones
  std::vector<double> edge_arrival;     ///< per edge [s]; infinite between held ends
  std::vector<std::uint32_t> vertices;  ///< the free vertices in order of arrival
  std::vector<std::uint32_t> edges;     ///< the pulling edges in order of arrival
  double vertexArrival(std::size_t i) const { return vertex_arrival[vertices[i]]; }
  double edgeArrival(std::size_t i) const { return edge_arrival[edges[i]]; }
};

WaveSchedule scheduleOf(const Scene& scene, const std::vector<double>& k,
                        const std::vector<double>& arrival) {
  const VertexSet& vertices = scene.vertices;
  const EdgeSet& edges = scene.edges;
  WaveSchedule schedule;
  schedule.vertex_arrival.assign(vertices.size(), kNever);
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (!vertices.isSupport(v)) schedule.vertex_arrival[v] = arrival[v];
  }
  schedule.edge_arrival.assign(edges.size(), kNever);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (k[e] == 0.0) continue;
    schedule.edge_arrival[e] = std::min(schedule.vertex_arrival[edges.vertex_a[e]],
                                        schedule.vertex_arrival[edges.vertex_b[e]]);
  }
  schedule.vertices = inOrderOf(schedule.vertex_arrival);
  schedule.edges = inOrderOf(schedule.edge_arrival);
  return schedule;
}

/// Adds the pull of the first `live` scheduled edges at time t [s] to `force` [N]; false when
/// one of them is longer than its tear length.
bool pullEdges(const Springs& springs, const WaveSchedule& schedule, std::size_t live,
               const WaveState& state, double t, const EdgeSet& edges,
               std::vector<Eigen::Vector3d>& force) {
  for (std::size_t i = 0; i < live; ++i) {
    const std::uint32_t e = schedule.edges[i];
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    const Eigen::Vector3d d = state.position(b, t) - state.position(a, t);
    const double length = d.norm();
    if (length > springs.tear_length[e]) return false;
    const double pull = springTension(springs.k[e], edges.rest_length[e], length);
    if (pull == 0.0) continue;
    const Eigen::Vector3d f = (pull / length) * d;
    force[a] += f;
    force[b] -= f;
  }
  return true;
}

/// Puts the ends of each edge of `springs.stops` that is longer than its breaking length back
/// onto it, moved in inverse proportion to their masses (an end that does not move counts as
/// held), and takes away their separating velocity (the stop is inelastic); one Gauss-Seidel
/// pass at time t [s].
void holdAtStops(const Springs& springs, const EdgeSet& edges, const WaveState& state, double t,
                 VertexSet& vertices) {
  for (std::uint32_t e : springs.stops) {
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    const double w_a = state.moving(a) ? 1.0 / vertices.mass[a] : 0.0;
    const double w_b = state.moving(b) ? 1.0 / vertices.mass[b] : 0.0;
    if (w_a + w_b == 0.0) continue;
    const Eigen::Vector3d d = state.position(b, t) - state.position(a, t);
    const double length = d.norm();
    if (!(length > springs.breaking_length[e])) continue;
    const Eigen::Vector3d u = d / length;
    const double share_a = w_a / (w_a + w_b);
    const double share_b = w_b / (w_a + w_b);
    const double excess = length - springs.breaking_length[e];
    if (w_a > 0.0) vertices.position[a] += (share_a * excess) * u;
    if (w_b > 0.0) vertices.position[b] -= (share_b * excess) * u;
    const Eigen::Vector3d v_a = w_a > 0.0 ? vertices.velocity[a] : Eigen::Vector3d::Zero();
    const Eigen::Vector3d v_b = w_b > 0.0 ? vertices.velocity[b] : Eigen::Vector3d::Zero();
    const double separating = u.dot(v_b - v_a);
    if (!(separating > 0.0)) continue;
    if (w_a > 0.0) vertices.velocity[a] += (share_a * separating) * u;
    if (w_b > 0.0) vertices.velocity[b] -= (share_b * separating) * u;
  }
}

}  // namespace

std::vector<Eigen::Vector3d> startAccelerations(const SimulationParameters& parameters,
                                                const Scene& scene) {
  const VertexSet& vertices = scene.vertices;
  const EdgeSet& edges = scene.edges;
  const std::vector<double> k = springStiffness(scene);
  std::vector<Eigen::Vector3d> force(vertices.size());
  accumulateExternalForces(parameters, vertices, force);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Eigen::Vector3d d =
        vertices.position[edges.vertex_b[e]] - vertices.position[edges.vertex_a[e]];
    const double length = d.norm();
    const double pull = springTension(k[e], edges.rest_length[e], length);
    if (pull == 0.0) continue;
    force[edges.vertex_a[e]] += (pull / length) * d;
    force[edges.vertex_b[e]] -= (pull / length) * d;
  }
  std::vector<Eigen::Vector3d> acceleration(vertices.size(), Eigen::Vector3d::Zero());
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (!vertices.isSupport(v)) acceleration[v] = force[v] / vertices.mass[v];
  }
  return acceleration;
}

RecoilWaveResult integrateRecoilWave(const SimulationParameters& parameters,
                                     const std::vector<double>& arrival,
                                     const std::vector<Eigen::Vector3d>& start_acceleration,
                                     double duration, Scene& scene, std::vector<double>& tension) {
  VertexSet& vertices = scene.vertices;
  const EdgeSet& edges = scene.edges;
  const Springs springs = springsOf(scene, parameters);
  RecoilWaveResult result;
  // Substeps at kCourant of the limit, the last one what remains: a chain's front rings by the
  // gap between the substep and its limit (3 % at 0.97, 7 % at 0.9), whatever the step's length.
  const double full = std::min(duration, kCourant * stableSubstep(scene, springs.k));
  result.substeps = std::max(1, static_cast<int>(std::ceil(duration / full - 1.0e-9)));
  const WaveSchedule schedule = scheduleOf(scene, springs.k, arrival);
  WaveState state(vertices, start_acceleration, duration);
  std::vector<Eigen::Vector3d> force(vertices.size(), Eigen::Vector3d::Zero());
  std::size_t moving = 0;  // schedule.vertices[0, moving) move
  std::size_t live = 0;    // schedule.edges[0, live) pull
  for (int s = 0; s < result.substeps; ++s) {
    const double t = s * full;
    const double h = s + 1 < result.substeps ? full : duration - t;
    for (; moving < schedule.vertices.size() && schedule.vertexArrival(moving) <= t; ++moving) {
      state.startMoving(schedule.vertices[moving], t, vertices);
    }
    while (live < schedule.edges.size() && schedule.edgeArrival(live) <= t) ++live;
    for (std::size_t i = 0; i < moving; ++i) {
      const std::uint32_t v = schedule.vertices[i];
      force[v] = springs.steady_force[v] - springs.drag[v] * vertices.velocity[v];
    }
    if (!pullEdges(springs, schedule, live, state, t, edges, force)) return result;
    for (std::size_t i = 0; i < moving; ++i) {
      const std::uint32_t v = schedule.vertices[i];
      vertices.velocity[v] += (h / vertices.mass[v]) * force[v];
      vertices.position[v] += h * vertices.velocity[v];
    }
    holdAtStops(springs, edges, state, t + h, vertices);
  }
  state.finish(vertices);
  tension.assign(edges.size(), 0.0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const double length =
        (vertices.position[edges.vertex_b[e]] - vertices.position[edges.vertex_a[e]]).norm();
    tension[e] = springTension(springs.k[e], edges.rest_length[e], length);
  }
  result.completed = true;
  return result;
}

}  // namespace yarn_tearing
