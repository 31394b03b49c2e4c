#pragma once

#include <cmath>
#include <vector>

#include "contact_test_support.hpp"

namespace yarn_tearing::test {

/// The radius of the capstan tests' post [m].
constexpr double kPostRadius = 5.0e-3;

/// A yarn wrapped round a post along y through the origin: straight tails on both sides and,
/// between them, chords tangent to the post that turn by `wrap_angle` [rad] in all. Vertex 0 is
/// end A (the tail on the left), the last vertex end B; `tail_direction_a` and
/// `tail_direction_b` are the unit outward directions of the two tails.
struct WrappedYarn {
  Scene scene;
  Eigen::Vector3d tail_direction_a;
  Eigen::Vector3d tail_direction_b;
  double segment = 0.0;  ///< chord length [m]
};

/// Wraps `spec`'s yarn (its material and radius) round a post of radius `post_radius` [m] over
/// `wrap_angle` [rad] with bends of at most `max_bend` [rad] and `tail_segments` chords per tail.
inline WrappedYarn wrappedYarn(YarnSpec spec, double post_radius, double wrap_angle,
                               int tail_segments, double max_bend = 0.4) {
  const int bends = std::max(1, static_cast<int>(std::ceil(wrap_angle / max_bend - 1e-9)));
  const double bend = wrap_angle / bends;
  const double contact_radius = post_radius + spec.radius;
  WrappedYarn w;
  w.segment = 2.0 * contact_radius * std::tan(bend / 2.0);
  const double rho = contact_radius / std::cos(bend / 2.0);
  // Bending vertices on a circle of radius rho in the xz plane, clockwise seen from +y,
  // symmetric about the top.
  const auto at = [](double angle, double radius) {
    return Eigen::Vector3d(radius * std::cos(angle), 0.0, radius * std::sin(angle));
  };
  std::vector<Eigen::Vector3d> arc;
  for (int k = 0; k < bends; ++k) {
    arc.push_back(at(kPi / 2.0 + (bends - 1) * bend / 2.0 - k * bend, rho));
  }
  // The heading into the first bend and out of the last (the chord headings turned by one bend).
  const auto turn = [](const Eigen::Vector3d& v, double angle) {
    return Eigen::Vector3d(std::cos(angle) * v.x() - std::sin(angle) * v.z(), 0.0,
                           std::sin(angle) * v.x() + std::cos(angle) * v.z());
  };
  const Eigen::Vector3d top = at(kPi / 2.0 + (bends - 1) * bend / 2.0 + bend / 2.0, 1.0);
  // Headings are tangent to the circle, clockwise: the one into the first bend is the tangent
  // half a bend before it.
  const Eigen::Vector3d heading_in(top.z(), 0.0, -top.x());
  w.tail_direction_a = -heading_in;
  w.tail_direction_b = turn(heading_in, -wrap_angle);
  std::vector<Eigen::Vector3d> points;
  for (int j = tail_segments; j >= 1; --j)
    points.push_back(arc[0] + j * w.segment * w.tail_direction_a);
  points.insert(points.end(), arc.begin(), arc.end());
  for (int j = 1; j <= tail_segments; ++j)
    points.push_back(arc.back() + j * w.segment * w.tail_direction_b);
  spec.pinned = {};
  spec.num_vertices = static_cast<int>(points.size());
  spec.length = w.segment * (spec.num_vertices - 1);
  w.scene = buildScene({spec});
  for (std::size_t v = 0; v < points.size(); ++v) w.scene.vertices.position[v] = points[v];
  return w;
}

}  // namespace yarn_tearing::test
