#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/contact/obstacle.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

/// One point where a yarn may touch an obstacle in this step: a vertex (on flat faces), or a
/// segment's closest point (on round solids, and inside a segment over a box's edge), so that a
/// long segment cannot pass through a thin peg. The point is p(x) = (1 - t) x_a + t x_b. Its rows
/// in the projection are of the length constraints' form (C(x) <= 0 or = 0, a multiplier m
/// [kg m] = force dt^2, the vertices moved by -W grad C m):
///   normal:   C_n = -(distance(p) - r) <= 0,  m_n >= 0 (pushes out, never pulls);
///   friction: C_k = -tau_k . (p - anchor) = 0 along each of two tangents tau_k while it
///             sticks along it (|m_k| <= mu m_n); once |m_k| would exceed mu m_n it slides along
///             tau_k, and friction is the known impulse +-mu m_n against the slip (Coulomb,
///             static = kinetic, on a pyramid: each tangent bounded on its own). The same rows at
///             a vertex and at a segment point.
struct Contact {
  /// The members below with an initializer get it; the vectors without one are set by detection
  /// (user-provided, so that building a record does not first zero all of it: a table's
  /// thousand points a step).
  Contact() {}  // NOLINT(modernize-use-equals-default)

  std::uint32_t a = 0;         ///< first vertex (global id)
  std::uint32_t b = 0;         ///< second vertex (= a for a vertex contact)
  double t = 0.0;              ///< weight of b in the contact point [-]
  std::uint32_t obstacle = 0;  ///< index of the obstacle
  double radius = 0.0;         ///< yarn radius r [m]
  double scale = 0.0;          ///< length the tolerances are relative to (edge length) [m]
  double friction = 0.0;       ///< mu [-]
  /// How much further than r the point keeps from a box's edges and corners [m]
  /// (contactRounding, edge_rounding.hpp; 0 on other shapes).
  double rounding = 0.0;
  Eigen::Vector3d normal;  ///< outward normal at the current linearization
  /// Unit tangents, normal x tangent[0] = tangent[1] (tangent[0] along the segment if any).
  Eigen::Vector3d tangent[2];
  double gap = 0.0;  ///< distance - r at the current linearization [m]
  /// Where a sticking point stays [m]: the point at parameter t of the segment between these two
  /// (where a and b started, carried by the obstacle), so that it follows t as the closest point
  /// moves along a segment lying tangent to a curved obstacle.
  Eigen::Vector3d anchor_a;
  Eigen::Vector3d anchor_b;     ///< see anchor_a [m]
  Eigen::Vector3d side_normal;  ///< outward normal at the step's start (the side it is on)
  Eigen::Vector3d side_point;   ///< surface point at the step's start [m]
  bool active = false;          ///< normal row taken as an equality
  /// False while a segment point sits at the segment's end, where its vertex's contact is.
  bool enabled = true;
  /// Per tangent: 0 while it sticks along it (a friction row), +1 or -1 while it slides with
  /// the known friction +-mu m_n along tangent[k] (on the yarn). Kept from step to step for the
  /// same point (ContactSet::detect), so a slipping zone starts the step as it ended the last.
  std::int8_t friction_sign[2] = {0, 0};
  /// False for a point new in this step until its first Newton step has given it a normal
  /// force: friction then has a meaningful bound (and sticks from the next Newton step on).
  bool friction_known = false;
  double normal_multiplier = 0.0;                              ///< m_n [kg m]
  Eigen::Vector3d friction_impulse = Eigen::Vector3d::Zero();  ///< on the yarn [kg m]

  /// The contact point of positions `x` [m].
  Eigen::Vector3d point(const std::vector<Eigen::Vector3d>& x) const {
    return (1.0 - t) * x[a] + t * x[b];
  }
  /// Tangents with a friction row or a sliding impulse each.
  static constexpr int kFrictionDirections = 2;
  /// How far the point moves per unit impulse on it [1/kg]: (1 - t)^2 w_a + t^2 w_b.
  double mobility(const std::vector<double>& inverse_mass) const {
    return (1.0 - t) * (1.0 - t) * inverse_mass[a] + t * t * inverse_mass[b];
  }
  /// Where the contact point sticks [m].
  Eigen::Vector3d anchor() const { return (1.0 - t) * anchor_a + t * anchor_b; }
  /// Impulse of the obstacle on the yarn at this point [kg m] (force times dt^2).
  Eigen::Vector3d impulse() const { return normal_multiplier * normal + friction_impulse; }
};

/// The contacts of one step: found from the positions at the step's start and the predicted
/// ones, linearized at each iterate of the projection, and the impulses they carried.
class ContactSet {
 public:
  /// What detection needs, per vertex and per edge.
  struct Input {
    const std::vector<Obstacle>* obstacles = nullptr;
    /// Each obstacle's pose at the start of the step (a sticking point moves with its obstacle).
    const std::vector<Eigen::Isometry3d>* previous_pose = nullptr;
    const std::vector<Eigen::Vector3d>* start = nullptr;      ///< x at the step's start [m]
    const std::vector<Eigen::Vector3d>* predicted = nullptr;  ///< x~ [m]
    const std::vector<double>* inverse_mass = nullptr;        ///< 0 for held vertices [1/kg]
    const std::vector<double>* vertex_radius = nullptr;       ///< yarn radius per vertex [m]
    const EdgeSet* edges = nullptr;
  };

  /// Finds every vertex and segment point that may touch an obstacle within this step (its
  /// distance at the start or the prediction below r plus what it and the obstacle move).
  void detect(const Input& input);
  /// Updates normals, tangents, gaps (and the segment parameter t) at positions `x` [m].
  void linearize(const std::vector<Eigen::Vector3d>& x);
  /// The curvature (Hessian of the distance) of contact `c`'s obstacle at its point [1/m].
  Eigen::Matrix3d curvature(const Contact& c, const std::vector<Eigen::Vector3d>& x) const {
    return (*obstacles_)[c.obstacle].curvature(c.point(x), c.rounding);
  }
  /// For a segment point inside its segment on a round solid, where the closest point moves
  /// along the segment as the segment turns: the segment's distance d(x_a, x_b) = min over t of
  /// distance((1 - t) x_a + t x_b) has the Hessian
  ///   Hess(distance at fixed t) - derivative derivative^T / second,
  /// with `derivative` = d/dt of the gradient on (x_a, x_b) [-, 1/m] (6 entries) and `second` =
  /// d^2 distance / dt^2 [m]. False where t does not move (a vertex, a segment's end, a box's face
  /// or sharp edge, a segment along a capsule's axis).
  bool closestPointTurn(const Contact& c, const std::vector<Eigen::Vector3d>& x,
                        Eigen::Matrix<double, 6, 1>& derivative, double& second) const;
  /// Largest penetration, relative to each contact's length scale [-] (0 if none).
  double maxPenetration() const;
  /// Adds `factor` w_v times each contact's impulse share to `sum` per vertex.
  void addImpulses(const std::vector<double>& inverse_mass, double factor,
                   std::vector<Eigen::Vector3d>& sum) const;
  /// Forgets the contacts of the last step (no contact in this one); the next detect() still
  /// carries their friction states, a second clear() forgets those too.
  void clear() {
    previous_.swap(contacts_);
    contacts_.clear();
  }

  /// Positions at the step's start given to the last detect() [m].
  const std::vector<Eigen::Vector3d>& start() const { return *start_; }
  std::vector<Contact>& contacts() { return contacts_; }
  const std::vector<Contact>& contacts() const { return contacts_; }
  bool empty() const { return contacts_.empty(); }

 private:
  void add(const Input& input, std::uint32_t obstacle, std::uint32_t a, std::uint32_t b, double t,
           double scale, double rounding);
  /// Distance [m] from `obstacle` (edges rounded by `rounding` [m]) and the normal at point `p`,
  /// on the side the step started (the point's outward normal `side_normal` and surface point
  /// `side_point` [m] there).
  static double sideDistance(const Obstacle& obstacle, double rounding,
                             const Eigen::Vector3d& side_normal, const Eigen::Vector3d& side_point,
                             const Eigen::Vector3d& p, Eigen::Vector3d& normal);
  /// True when no point of segment (a, b), whose predicted middle is `middle` [m] and half
  /// length `half` [m], can come within add()'s reach of `obstacle` (`scale` [m] as add()'s):
  /// a bound from the obstacle's distance at the middle, before the closest point is sought.
  bool clearOfReach(const Input& input, std::uint32_t obstacle, std::uint32_t a, std::uint32_t b,
                    const Eigen::Vector3d& middle, double half, double scale) const;

  const std::vector<Obstacle>* obstacles_ = nullptr;
  /// The friction states of the last step's point
  /// on the same segment (or vertex) and obstacle, if it had one.
  void carryFrictionStates(Contact& c);

  const std::vector<Eigen::Vector3d>* start_ = nullptr;
  std::vector<Contact> contacts_;
  std::vector<Contact> previous_;          ///< the last step's contacts, while detecting [-]
  bool previous_sorted_ = false;           ///< previous_ sorted by (obstacle, a, b) in this detect
  std::vector<Eigen::Isometry3d> motion_;  ///< per obstacle: pose times the step's start pose^-1
  std::vector<double> scale_;              ///< per vertex: its longest edge [m]
};

}  // namespace yarn_tearing
