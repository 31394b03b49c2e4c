#include "yarn_tearing/core/contact/obstacle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace yarn_tearing {
namespace {

constexpr double kLargestSize = 1.0e4;  ///< [m], as the yarns' coordinates

/// Newton steps that polish a segment's closest point on a box after the golden-section search.
constexpr int kClosestPointPolish = 3;

void requireSize(const std::string& name, const char* field, double value) {
  if (!(value > 0.0 && value <= kLargestSize)) {
    throw std::invalid_argument("obstacle '" + name + "': " + field +
                                " must be a finite number in (0, 1e4] [m]");
  }
}

/// How far a box is shrunk to round its edges by `rounding` [m]: at most its smallest half
/// extent, so that the faces stay where they are.
double boxRounding(const Obstacle& o, double rounding) {
  return std::min(rounding, o.half_extents.minCoeff());
}

/// Signed distance of a point in the obstacle's frame, with its outward normal (obstacle frame)
/// unless `normal` is null (detection's quick rejection needs the distance only); a box's edges
/// and corners rounded by `rounding` [m].
double localDistance(const Obstacle& o, const Eigen::Vector3d& p, Eigen::Vector3d* normal,
                     double rounding) {
  switch (o.shape) {
    case ObstacleShape::kPlane:
      if (normal != nullptr) *normal = Eigen::Vector3d::UnitZ();
      return p.z();
    case ObstacleShape::kSphere: {
      const double r = p.norm();
      if (normal != nullptr) *normal = r > 0.0 ? Eigen::Vector3d(p / r) : Eigen::Vector3d::UnitZ();
      return r - o.radius;
    }
    case ObstacleShape::kCapsule: {
      const Eigen::Vector3d axis_point(0.0, 0.0, std::clamp(p.z(), -o.half_length, o.half_length));
      const Eigen::Vector3d d = p - axis_point;
      const double r = d.norm();
      if (normal != nullptr) *normal = r > 0.0 ? Eigen::Vector3d(d / r) : Eigen::Vector3d::UnitX();
      return r - o.radius;
    }
    case ObstacleShape::kBox: {
      // The box shrunk by s, then every distance less s: faces unchanged, edges and corners
      // rounded to radius s.
      const double s = boxRounding(o, rounding);
      const Eigen::Vector3d q = p.cwiseAbs() - (o.half_extents.array() - s).matrix();
      const Eigen::Vector3d outside = q.cwiseMax(0.0);
      const double out = outside.norm();
      if (out > 0.0) {
        if (normal != nullptr) *normal = outside.cwiseProduct(p.cwiseSign()) / out;
        return out - s;
      }
      Eigen::Index axis = 0;
      const double in = q.maxCoeff(&axis);  // <= 0: the nearest face
      if (normal != nullptr) {
        *normal = Eigen::Vector3d::Zero();
        (*normal)[axis] = p[axis] >= 0.0 ? 1.0 : -1.0;
      }
      return in - s;
    }
  }
  if (normal != nullptr) *normal = Eigen::Vector3d::UnitZ();
  return std::numeric_limits<double>::infinity();
}

/// Parameter t in [0, 1] of the point la + t ab closest to the axis segment z in [-h, h]
/// (closest points of two segments, as in Ericson, Real-Time Collision Detection, 5.1.9).
double closestToAxis(const Eigen::Vector3d& la, const Eigen::Vector3d& ab, double h) {
  const Eigen::Vector3d d2(0.0, 0.0, 2.0 * h);
  const Eigen::Vector3d r = la - Eigen::Vector3d(0.0, 0.0, -h);
  const double a = ab.squaredNorm();
  const double e = d2.squaredNorm();
  const double f = d2.dot(r);
  if (!(a > 0.0)) return 0.0;
  const double c = ab.dot(r);
  const double b = ab.dot(d2);
  const double denominator = a * e - b * b;
  double s =
      denominator > 1e-14 * a * e ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  const double u = (b * s + f) / e;
  if (u < 0.0) {
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (u > 1.0) {
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return s;
}

/// `p` [m] in the frame of `pose` (R^T (p - t): cheaper than forming the inverse transform, which
/// detection would do a few thousand times a step on a table).
Eigen::Vector3d toLocal(const Eigen::Isometry3d& pose, const Eigen::Vector3d& p) {
  return pose.linear().transpose() * (p - pose.translation());
}

}  // namespace

bool Obstacle::sameGeometry(const Obstacle& other) const {
  return shape == other.shape && pose.matrix() == other.pose.matrix() &&
         half_extents == other.half_extents && radius == other.radius &&
         half_length == other.half_length && edge_radius == other.edge_radius;
}

void Obstacle::validate() const {
  if (!pose.matrix().allFinite()) {
    throw std::invalid_argument("obstacle '" + name + "': pose must be finite");
  }
  if (!pose.translation().allFinite() || pose.translation().norm() > kLargestSize) {
    throw std::invalid_argument("obstacle '" + name + "': position must be within 1e4 m");
  }
  if (!(friction >= 0.0 && friction <= 10.0)) {
    throw std::invalid_argument("obstacle '" + name +
                                "': friction must be a finite number in [0, 10] [-]");
  }
  switch (shape) {
    case ObstacleShape::kPlane:
      break;
    case ObstacleShape::kBox:
      for (int i = 0; i < 3; ++i) requireSize(name, "half_extents", half_extents[i]);
      if (!(edge_radius >= 0.0 && edge_radius <= half_extents.minCoeff())) {
        throw std::invalid_argument("obstacle '" + name +
                                    "': edge_radius must be a finite number in [0, the smallest "
                                    "half extent] [m]");
      }
      break;
    case ObstacleShape::kSphere:
      requireSize(name, "radius", radius);
      break;
    case ObstacleShape::kCapsule:
      requireSize(name, "radius", radius);
      requireSize(name, "half_length", half_length);
      break;
  }
}

double Obstacle::solidDistance(const Eigen::Vector3d& p, Eigen::Vector3d& normal,
                               double rounding) const {
  Eigen::Vector3d local_normal;
  const double distance = localDistance(*this, toLocal(pose, p), &local_normal, rounding);
  normal = pose.linear() * local_normal;
  return distance;
}

double Obstacle::signedDistance(const Eigen::Vector3d& p, double rounding) const {
  return localDistance(*this, toLocal(pose, p), nullptr, rounding);
}

double Obstacle::closestOnSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  double rounding) const {
  const Eigen::Vector3d la = toLocal(pose, a);
  const Eigen::Vector3d ab = pose.linear().transpose() * (b - a);
  const double ab2 = ab.squaredNorm();
  switch (shape) {
    case ObstacleShape::kPlane:
      // Linear along the segment: an end is closest (the first one on a tie).
      return ab.z() < 0.0 ? 1.0 : 0.0;
    case ObstacleShape::kSphere:
      return ab2 > 0.0 ? std::clamp(-la.dot(ab) / ab2, 0.0, 1.0) : 0.0;
    case ObstacleShape::kCapsule:
      return closestToAxis(la, ab, half_length);
    case ObstacleShape::kBox:
      break;
  }
  // Golden-section search of the convex distance along the segment.
  constexpr double kInverseGolden = 0.6180339887498949;
  double lo = 0.0;
  double hi = 1.0;
  double t1 = hi - kInverseGolden * (hi - lo);
  double t2 = lo + kInverseGolden * (hi - lo);
  double f1 = signedDistance(a + t1 * (b - a), rounding);
  double f2 = signedDistance(a + t2 * (b - a), rounding);
  for (int i = 0; i < 40; ++i) {
    if (f1 <= f2) {
      hi = t2;
      t2 = t1;
      f2 = f1;
      t1 = hi - kInverseGolden * (hi - lo);
      f1 = signedDistance(a + t1 * (b - a), rounding);
    } else {
      lo = t1;
      t1 = t2;
      f1 = f2;
      t2 = lo + kInverseGolden * (hi - lo);
      f2 = signedDistance(a + t2 * (b - a), rounding);
    }
  }
  double t = 0.5 * (lo + hi);
  const double ft = signedDistance(a + t * (b - a), rounding);
  const double fa = signedDistance(a, rounding);
  const double fb = signedDistance(b, rounding);
  if (fa <= ft && fa <= fb) return 0.0;
  if (fb <= ft) return 1.0;
  // The search leaves t uncertain by 0.618^40 = 4e-9; where the surface curves (a rounded edge)
  // the normal there is then off perpendicular to the segment by that much, which a Newton
  // solve of the contact rows cannot settle (its force balance stalled at 1e-3 of an edge).
  // Newton steps on d/dt distance = n . (b - a) make it exact.
  const Eigen::Vector3d e = b - a;
  for (int i = 0; i < kClosestPointPolish; ++i) {
    const Eigen::Vector3d p = a + t * e;
    const double second = e.dot(curvature(p, rounding) * e);
    if (!(second > 0.0)) break;
    Eigen::Vector3d normal;
    signedDistance(p, normal, rounding);
    const double next = std::clamp(t - normal.dot(e) / second, 0.0, 1.0);
    if (next == t) break;
    t = next;
  }
  return t;
}

Eigen::Matrix3d Obstacle::curvature(const Eigen::Vector3d& p, double rounding) const {
  const Eigen::Vector3d local = toLocal(pose, p);
  Eigen::Vector3d normal;
  const double distance = localDistance(*this, local, &normal, rounding) + radius;
  const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - normal * normal.transpose();
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  switch (shape) {
    case ObstacleShape::kPlane:
      break;
    case ObstacleShape::kSphere:
      if (distance > 0.0) h = across / distance;
      break;
    case ObstacleShape::kCapsule:
      if (distance > 0.0) {
        // Along the axis the cylindrical part does not curve.
        const bool on_side = std::abs(local.z()) < half_length;
        const Eigen::Matrix3d axis =
            Eigen::Vector3d::UnitZ() * Eigen::Vector3d::UnitZ().transpose();
        h = (on_side ? Eigen::Matrix3d(across - axis) : across) / distance;
      }
      break;
    case ObstacleShape::kBox: {
      // Outside an edge or a corner of the shrunk box the distance is to a line or a point.
      const Eigen::Vector3d q =
          local.cwiseAbs() - (half_extents.array() - boxRounding(*this, rounding)).matrix();
      const Eigen::Vector3d outside = q.cwiseMax(0.0);
      const double d = outside.norm();
      const int count = (outside.array() > 0.0).count();
      if (d > 0.0 && count >= 2) {
        h = across;
        if (count == 2) {
          Eigen::Index axis = 0;
          q.minCoeff(&axis);
          h -= Eigen::Vector3d::Unit(axis) * Eigen::Vector3d::Unit(axis).transpose();
        }
        h /= d;
      }
      break;
    }
  }
  return pose.linear() * h * pose.linear().transpose();
}

double Obstacle::boundingRadius() const {
  switch (shape) {
    case ObstacleShape::kPlane:
      return std::numeric_limits<double>::infinity();
    case ObstacleShape::kBox:
      return half_extents.norm();
    case ObstacleShape::kSphere:
      return radius;
    case ObstacleShape::kCapsule:
      return radius + half_length;
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace yarn_tearing
