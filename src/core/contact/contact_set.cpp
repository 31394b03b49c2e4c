#include "yarn_tearing/core/contact/contact_set.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "yarn_tearing/core/contact/edge_rounding.hpp"

namespace yarn_tearing {
namespace {

/// Segment points this close to an end are left to that end's vertex contact [-].
constexpr double kEndFraction = 0.02;

/// Smallest curvature along a segment, relative to the surface's mean curvature, for which its
/// closest point is well defined [-].
constexpr double kFlatTurn = 1e-2;

/// A unit vector orthogonal to unit `n`.
Eigen::Vector3d orthogonal(const Eigen::Vector3d& n) {
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return n.cross(helper).normalized();
}

}  // namespace

void ContactSet::detect(const Input& input) {
  obstacles_ = input.obstacles;
  start_ = input.start;
  if (!contacts_.empty()) previous_.swap(contacts_);
  contacts_.clear();
  contacts_.reserve(previous_.size());
  previous_sorted_ = false;
  const std::vector<Obstacle>& obstacles = *input.obstacles;
  // Each obstacle's motion over the step, once per obstacle rather than per point.
  motion_.resize(obstacles.size());
  for (std::size_t o = 0; o < obstacles.size(); ++o) {
    motion_[o] = obstacles[o].pose * (*input.previous_pose)[o].inverse(Eigen::Isometry);
  }
  const std::vector<Eigen::Vector3d>& predicted = *input.predicted;
  const std::vector<double>& w = *input.inverse_mass;
  const EdgeSet& edges = *input.edges;
  // Each vertex's length scale: its longest edge (torn ones too, so a loose end keeps one).
  scale_.assign(predicted.size(), 0.0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    for (const std::uint32_t v : {edges.vertex_a[e], edges.vertex_b[e]}) {
      scale_[v] = std::max(scale_[v], edges.rest_length[e]);
    }
  }
  for (std::uint32_t o = 0; o < obstacles.size(); ++o) {
    const Obstacle& obstacle = obstacles[o];
    const double bound = obstacle.boundingRadius();
    const Eigen::Vector3d center = obstacle.pose.translation();
    const auto far = [&](const Eigen::Vector3d& p, std::uint32_t v, double extent) {
      const double reach = extent + scale_[v] + (*input.vertex_radius)[v] +
                           (predicted[v] - (*input.start)[v]).norm();
      return std::isfinite(bound) && (p - center).norm() > bound + reach;
    };
    // On a round solid each segment has one contact, at its closest point, ends included (two
    // segments meeting at a vertex may both touch it there: their rows then share the push).
    // On flat faces the closest points are vertices, and a segment point is added only where
    // the distance has an inner minimum (a box's edge; never on a plane, linear along a segment).
    const bool round =
        obstacle.shape == ObstacleShape::kSphere || obstacle.shape == ObstacleShape::kCapsule;
    for (std::uint32_t v = 0; v < predicted.size() && !round; ++v) {
      if (w[v] == 0.0 || scale_[v] == 0.0 || far(predicted[v], v, 0.0)) continue;
      add(input, o, v, v, 0.0, scale_[v],
          contactRounding(obstacle, (*input.vertex_radius)[v], scale_[v]));
    }
    if (obstacle.shape == ObstacleShape::kPlane) continue;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (!edges.intact(e)) continue;
      const std::uint32_t a = edges.vertex_a[e];
      const std::uint32_t b = edges.vertex_b[e];
      if (w[a] + w[b] == 0.0) continue;
      const Eigen::Vector3d& xa = predicted[a];
      const Eigen::Vector3d& xb = predicted[b];
      const Eigen::Vector3d middle = (xa + xb) / 2;
      const double half = (xa - xb).norm() / 2;
      if (far(middle, a, half) ||
          clearOfReach(input, o, a, b, middle, half, edges.rest_length[e])) {
        continue;
      }
      const double rounding =
          contactRounding(obstacle, (*input.vertex_radius)[a], edges.rest_length[e]);
      const double t = obstacle.closestOnSegment(xa, xb, rounding);
      if (round || (t > kEndFraction && t < 1.0 - kEndFraction)) {
        add(input, o, a, b, t, edges.rest_length[e], rounding);
      }
    }
  }
}

bool ContactSet::clearOfReach(const Input& input, std::uint32_t obstacle, std::uint32_t a,
                              std::uint32_t b, const Eigen::Vector3d& middle, double half,
                              double scale) const {
  // add() keeps a segment's point when its gap at the prediction (at the predicted closest point
  // p) or at the start (at the start segment's closest point s, carried by the obstacle's
  // motion) is within reach = scale + |p - s|. Each end moves by at most `move` (start carried
  // to prediction), so every point of the start segment is within `move` of the predicted
  // segment's point of the same parameter, and |p - s| <= 2 half + move. Every predicted point
  // is within `half` of the middle, so the predicted gap is at least
  // lower = distance(middle) - half - r and the start gap at least lower - move (the distance is
  // 1-Lipschitz). So a segment with lower > scale + 2 (half + move) is one add() would drop (and
  // its normals at p and s are on the same side: a convex solid's normals at two points closer
  // than either's distance make an angle below 90 degrees).
  const Eigen::Isometry3d& motion = motion_[obstacle];
  const std::vector<Eigen::Vector3d>& start = *input.start;
  const std::vector<Eigen::Vector3d>& predicted = *input.predicted;
  const double move = std::max((predicted[a] - motion * start[a]).norm(),
                               (predicted[b] - motion * start[b]).norm());
  const double lower =
      (*input.obstacles)[obstacle].signedDistance(middle) - half - (*input.vertex_radius)[a];
  return lower > scale + 2.0 * (half + move);
}

void ContactSet::add(const Input& input, std::uint32_t obstacle, std::uint32_t a, std::uint32_t b,
                     double t, double scale, double rounding) {
  const Obstacle& o = (*input.obstacles)[obstacle];
  const double radius = (*input.vertex_radius)[a];
  const std::vector<Eigen::Vector3d>& start_position = *input.start;
  const std::vector<Eigen::Vector3d>& predicted_position = *input.predicted;
  // The side the point starts on: its start position carried along by the obstacle's motion,
  // at the start segment's own closest point. (The predicted segment's closest point can be far
  // from it: at dt 1e-2 a wrapped chord's moved by 0.4 % of the chord, which put a chord that
  // pushed at the step's start 1.8 nm off the 5 mm post, past the 1 nm of `touching` below; it
  // lost its friction states, and the wrap slid off the post at 0.97 of the capstan law.)
  const Eigen::Isometry3d& motion = motion_[obstacle];
  const Eigen::Vector3d start_a = motion * start_position[a];
  const Eigen::Vector3d start_b = a == b ? start_a : Eigen::Vector3d(motion * start_position[b]);
  double start_t = t;
  if (a != b) {
    start_t = o.closestOnSegment(start_a, start_b, rounding);
    if (o.shape == ObstacleShape::kBox) {
      start_t = std::clamp(start_t, kEndFraction, 1.0 - kEndFraction);
    }
  }
  const Eigen::Vector3d start = (1.0 - start_t) * start_a + start_t * start_b;
  Eigen::Vector3d side_normal;
  const double start_distance = o.signedDistance(start, side_normal, rounding);
  const Eigen::Vector3d side_point = start - start_distance * side_normal;
  Eigen::Vector3d normal;
  const Eigen::Vector3d predicted = (1.0 - t) * predicted_position[a] + t * predicted_position[b];
  const double predicted_gap =
      sideDistance(o, rounding, side_normal, side_point, predicted, normal) - radius;
  const double reach = scale + (predicted - start).norm();
  if (std::min(start_distance - radius, predicted_gap) > reach) return;
  // Built in place: a table's thousand points a step.
  Contact& c = contacts_.emplace_back();
  c.a = a;
  c.b = b;
  c.t = t;
  c.obstacle = obstacle;
  c.radius = radius;
  c.scale = scale;
  c.friction = o.friction;
  c.rounding = rounding;
  c.side_normal = side_normal;
  c.side_point = side_point;
  // A point touching at the start sticks where it was; one arriving, where it arrives.
  const bool touching = start_distance - radius <= 1e-6 * scale;
  if (touching) {
    c.anchor_a = start_a;
    c.anchor_b = start_b;
  } else {
    const Eigen::Vector3d arrival = -std::min(predicted_gap, 0.0) * normal;
    c.anchor_a = predicted_position[a] + arrival;
    c.anchor_b = predicted_position[b] + arrival;
  }
  c.active = predicted_gap < 0.0;
  if (touching) carryFrictionStates(c);
}

void ContactSet::carryFrictionStates(Contact& c) {
  const auto key = [](const Contact& k) { return std::make_tuple(k.obstacle, k.a, k.b); };
  // Detection finds the points in the same order from step to step while the yarn stays where
  // it is (a yarn at rest): the point at the same place in the last step's list is tried first,
  // the sorted list searched only when it is another.
  const std::size_t index = contacts_.size() - 1;  // c is the last one added
  auto it = previous_.begin() + static_cast<std::ptrdiff_t>(index);
  if (index >= previous_.size() || key(*it) != key(c)) {
    if (!previous_sorted_) {
      std::sort(previous_.begin(), previous_.end(),
                [&](const Contact& l, const Contact& r) { return key(l) < key(r); });
      previous_sorted_ = true;
    }
    it = std::lower_bound(previous_.begin(), previous_.end(), c,
                          [&](const Contact& l, const Contact& r) { return key(l) < key(r); });
  }
  if (it == previous_.end() || key(*it) != key(c) || !it->active) return;
  for (int k = 0; k < Contact::kFrictionDirections; ++k) c.friction_sign[k] = it->friction_sign[k];
  c.friction_known = true;
}

double ContactSet::sideDistance(const Obstacle& obstacle, double rounding,
                                const Eigen::Vector3d& side_normal,
                                const Eigen::Vector3d& side_point, const Eigen::Vector3d& p,
                                Eigen::Vector3d& normal) {
  const double d = obstacle.signedDistance(p, normal, rounding);
  if (normal.dot(side_normal) >= 0.0) return d;
  // Through to the other side (a thin peg, a fast yarn): hold it on the side it came from.
  normal = side_normal;
  return side_normal.dot(p - side_point);
}

void ContactSet::linearize(const std::vector<Eigen::Vector3d>& x) {
  // A face's points share their normal: its orthogonal tangent is found once.
  Eigen::Vector3d last_normal = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_orthogonal = Eigen::Vector3d::Zero();
  for (Contact& c : contacts_) {
    // A segment point follows the segment's closest point at every iterate, so that its row is
    // the gradient of the segment's own distance (the Newton steps add the curvature that
    // moving t gives, closestPointTurn). On a box, where the closest point may leave the
    // segment's inside for a vertex, it is handed to that vertex's contact there.
    bool at_end = false;
    const bool box = (*obstacles_)[c.obstacle].shape == ObstacleShape::kBox;
    if (c.a != c.b) {
      const double t = (*obstacles_)[c.obstacle].closestOnSegment(x[c.a], x[c.b], c.rounding);
      if (box) {
        at_end = t <= kEndFraction || t >= 1.0 - kEndFraction;
        c.t = std::clamp(t, kEndFraction, 1.0 - kEndFraction);
      } else {
        c.t = t;
      }
    }
    c.gap = sideDistance((*obstacles_)[c.obstacle], c.rounding, c.side_normal, c.side_point,
                         c.point(x), c.normal) -
            c.radius;
    c.enabled = !at_end;
    if (at_end) {
      // The segment's closest point has moved to an end, whose vertex contact holds it: two
      // rows on the same point would make the system singular.
      c.gap = std::max(c.gap, 0.0);
      c.active = false;
      c.normal_multiplier = 0.0;
      c.friction_impulse.setZero();
    }
    const Eigen::Vector3d axis = x[c.b] - x[c.a];
    const Eigen::Vector3d along = axis - c.normal.dot(axis) * c.normal;
    if (c.a != c.b && along.norm() > 1e-9 * axis.norm()) {
      c.tangent[0] = along.normalized();
    } else {
      if (c.normal != last_normal) {
        last_normal = c.normal;
        last_orthogonal = orthogonal(c.normal);
      }
      c.tangent[0] = last_orthogonal;
    }
    c.tangent[1] = c.normal.cross(c.tangent[0]);
  }
}

bool ContactSet::closestPointTurn(const Contact& c, const std::vector<Eigen::Vector3d>& x,
                                  Eigen::Matrix<double, 6, 1>& derivative, double& second) const {
  if (c.a == c.b || !(c.t > 0.0 && c.t < 1.0)) return false;
  if ((*obstacles_)[c.obstacle].shape == ObstacleShape::kBox && !(c.rounding > 0.0)) return false;
  const Eigen::Vector3d e = x[c.b] - x[c.a];
  const Eigen::Matrix3d h = curvature(c, x);
  second = e.dot(h * e);
  // Along the surface's flat direction (a segment along a capsule's axis) t is not defined.
  if (!(second > kFlatTurn * e.squaredNorm() * h.trace())) return false;
  derivative.head<3>() = (1.0 - c.t) * (h * e) - c.normal;
  derivative.tail<3>() = c.t * (h * e) + c.normal;
  return true;
}

double ContactSet::maxPenetration() const {
  double worst = 0.0;
  for (const Contact& c : contacts_) worst = std::max(worst, -c.gap / c.scale);
  return worst;
}

void ContactSet::addImpulses(const std::vector<double>& inverse_mass, double factor,
                             std::vector<Eigen::Vector3d>& sum) const {
  for (const Contact& c : contacts_) {
    const Eigen::Vector3d p = factor * c.impulse();
    sum[c.a] += ((1.0 - c.t) * inverse_mass[c.a]) * p;
    if (c.b != c.a) sum[c.b] += (c.t * inverse_mass[c.b]) * p;
  }
}

}  // namespace yarn_tearing
