#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/contact/contact_set.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

/// The fast path for a yarn resting on flat faces (a table, a box's top): a vertex contact that
/// pushed and stuck along both tangents at the end of the last step (its states carried by
/// ContactSet::detect) is guessed to stick again. Its normal row and two friction rows are then
/// three orthonormal equalities on one vertex: together they hold the vertex where it stuck,
/// on the surface, exactly as a pin would. The projection then runs its fast iterations with
/// those vertices as supports (no contact rows), and the guess is verified afterwards: each held
/// vertex's contact impulse, what its momentum balance needs beyond its edges' forces, must push
/// (m_n > 0) and lie in the friction pyramid (|m_k| <= mu m_n along both tangents), and no other
/// contact point may penetrate. Then it is the solution of the full complementarity problem (the
/// same rows the Newton steps would carry, at the same fixed point); otherwise the projection
/// falls back to the Newton steps with contact rows.
/// On a frictionless face (mu = 0) a vertex contact that pushed in the last step has its normal
/// row only: the vertex is kept on the face (put on it, then moved within it: its corrections
/// lose their component along the normal, i.e. its mobility is w (I - n n^T)) and otherwise
/// moves freely. Its contact impulse, the normal part of what its momentum balance needs, must
/// push; it has no friction.
/// When every contact point but those is one that the prediction leaves clear of its obstacle
/// and that pushed nothing in the last step (an obstacle beside a patch, within the detection
/// margin), those are guessed to stay clear: no rows, no impulses, and the guess holds when
/// none penetrates at the end.
class RestingContacts {
 public:
  /// Picks the held vertices from `contacts` (detected, not yet linearized) and each one's target
  /// position [m], and with `faces` the vertices kept on frictionless faces; handled() then
  /// marks the contacts it takes care of: the holding ones, segment points between two held
  /// vertices (on a face with them; checked by accept()), and, when every other point is one the
  /// prediction leaves clear of its obstacle and that pushed nothing in the last step, those
  /// (guessed to stay clear, without impulse; checked by accept()).
  void select(const ContactSet& contacts, const std::vector<double>& inverse_mass, bool faces);
  /// Some vertex is held or kept on a face.
  bool any() const { return !held_.empty() || !on_face_.empty(); }
  /// Some vertex is kept on a frictionless face.
  bool anyOnFace() const { return !on_face_.empty(); }
  /// Per vertex: 1 where it is kept on a frictionless face.
  const std::vector<std::uint8_t>& onFaceMask() const { return on_face_mask_; }
  /// Per contact: 1 where select() takes care of it (the others need rows).
  const std::vector<std::uint8_t>& handled() const { return handled_; }
  /// Gives every contact the state select() found it in (active as detected, no impulse), for
  /// the full solve after a failed fast path (linearize() releases a box's segment point whose
  /// closest point reached its end; the fast path stores impulses).
  void restore(ContactSet& contacts) const;
  /// Moves each held vertex of `position` to its target and zeroes its `inverse_mass`; puts each
  /// vertex kept on a face onto it.
  void hold(std::vector<Eigen::Vector3d>& position, std::vector<double>& inverse_mass) const;
  /// Puts each vertex kept on a face back onto it (after a correction, which it takes within
  /// the face only) [m].
  void keepOnFaces(std::vector<Eigen::Vector3d>& position) const;
  /// Removes the face normal's component from `sum` [any unit] at each vertex kept on a face.
  void dropFaceNormals(std::vector<Eigen::Vector3d>& sum) const;
  /// Verifies the guess after the projection and, if it holds, stores each contact's impulse
  /// (held ones from their vertices' momentum balance less the other contacts' impulses on them,
  /// the other handled ones none). `position` is final,
  /// `predicted` the positions before the projection [m], `inverse_mass` the vertices' own
  /// (held ones not zeroed) [1/kg], `multiplier` each intact edge's multiplier [kg m],
  /// `tolerance` the relative penetration allowed [-], `linearized` true when `contacts` are
  /// linearized at `position` already (else it is done here). After false, restore() before
  /// the full solve.
  bool accept(ContactSet& contacts, const std::vector<Eigen::Vector3d>& position,
              const std::vector<Eigen::Vector3d>& predicted,
              const std::vector<double>& inverse_mass, const EdgeSet& edges,
              const std::vector<double>& multiplier, double tolerance, bool linearized);

 private:
  /// Per vertex: the index of the contact holding it (or keeping it on a face), -1 if none.
  std::vector<std::int32_t> held_by_;
  /// A vertex kept on a frictionless face: the plane n . x = offset it stays in.
  struct OnFace {
    std::uint32_t vertex = 0;
    Eigen::Vector3d normal;  ///< the face's outward unit normal n
    double offset = 0.0;     ///< n . x on the face, a yarn radius out [m]
  };
  std::vector<OnFace> on_face_;
  std::vector<std::uint8_t> on_face_mask_;  ///< see onFaceMask()
  /// Per vertex: the contact index of its vertex contact (-1 none, -2 more than one).
  std::vector<std::int32_t> vertex_contact_;
  std::vector<std::uint32_t> held_;      ///< the held vertices
  std::vector<Eigen::Vector3d> target_;  ///< per held vertex: where it sticks [m]
  /// Per vertex: the impulses of its edges and of the contacts not handled here on it [kg m].
  std::vector<Eigen::Vector3d> other_impulse_;
  std::vector<std::uint8_t> was_active_;  ///< per contact: active as detected
  std::vector<std::uint8_t> handled_;     ///< see handled()
};

}  // namespace yarn_tearing
