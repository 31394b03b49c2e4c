#include "yarn_tearing/core/contact/resting_contacts.hpp"

#include <cmath>

namespace yarn_tearing {
namespace {

/// Whether `c` is a vertex contact that pushed and stuck along both tangents in the last step
/// (ContactSet carries those states) and is predicted to push again.
bool stuckVertexContact(const Contact& c) {
  if (c.a != c.b || !(c.friction > 0.0) || !c.friction_known || !c.active) return false;
  for (int k = 0; k < Contact::kFrictionDirections; ++k) {
    if (c.friction_sign[k] != 0) return false;
  }
  return true;
}

/// Whether `c` is a vertex contact on a frictionless face that pushed in the last step and is
/// predicted to push again.
bool frictionlessVertexContact(const Contact& c) {
  return c.a == c.b && c.friction == 0.0 && c.friction_known && c.active;
}

/// Whether `c` is a point that the prediction leaves clear of its obstacle (inactive as
/// detected) and that pushed nothing at the end of the last step (no friction states carried):
/// a taut wrap's points, which its tension presses in again whatever the prediction, are not.
bool clearPoint(const Contact& c) { return !c.active && !c.friction_known; }

}  // namespace

void RestingContacts::select(const ContactSet& contacts, const std::vector<double>& inverse_mass,
                             bool faces) {
  const std::vector<Contact>& list = contacts.contacts();
  const std::size_t n = inverse_mass.size();
  vertex_contact_.assign(n, -1);
  held_by_.assign(n, -1);
  held_.clear();
  target_.clear();
  on_face_.clear();
  on_face_mask_.assign(n, 0);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Contact& c = list[i];
    if (c.a != c.b) continue;
    std::int32_t& slot = vertex_contact_[c.a];
    slot = slot == -1 ? static_cast<std::int32_t>(i) : -2;
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Contact& c = list[i];
    if (stuckVertexContact(c) && inverse_mass[c.a] > 0.0 &&
        vertex_contact_[c.a] == static_cast<std::int32_t>(i)) {
      held_by_[c.a] = static_cast<std::int32_t>(i);
      held_.push_back(c.a);
      // Vertex contacts are on flat faces: the point where it stuck, moved along the face's
      // normal onto the surface (distance r).
      const Eigen::Vector3d anchor = c.anchor();
      target_.push_back(anchor +
                        (c.radius - c.side_normal.dot(anchor - c.side_point)) * c.side_normal);
    } else if (faces && frictionlessVertexContact(c) && inverse_mass[c.a] > 0.0 &&
               vertex_contact_[c.a] == static_cast<std::int32_t>(i)) {
      held_by_[c.a] = static_cast<std::int32_t>(i);
      on_face_mask_[c.a] = 1;
      on_face_.push_back({c.a, c.side_normal, c.side_normal.dot(c.side_point) + c.radius});
    }
  }
  was_active_.resize(list.size());
  handled_.resize(list.size());
  bool all_clear = true;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Contact& c = list[i];
    was_active_[i] = c.active ? 1 : 0;
    // A segment point between two vertices on a frictionless face keeps its row.
    const bool held =
        held_by_[c.a] >= 0 && held_by_[c.b] >= 0 && !on_face_mask_[c.a] && !on_face_mask_[c.b];
    handled_[i] = held || (c.a == c.b && on_face_mask_[c.a] != 0 &&
                           held_by_[c.a] == static_cast<std::int32_t>(i))
                      ? 1
                      : 0;
    all_clear = all_clear && (handled_[i] != 0 || clearPoint(c));
  }
  // When every other point is clear, none needs a row: each is guessed to stay clear, without
  // impulse (accept() finds it unpenetrated at the end; zero impulses then satisfy its
  // complementarity and friction). Where some point needs a row, the clear ones keep theirs
  // too, as the fast iterations' rows (FastContactRows) or the Newton steps take them.
  if (!all_clear) return;
  for (std::size_t i = 0; i < list.size(); ++i) handled_[i] = 1;
}

void RestingContacts::restore(ContactSet& contacts) const {
  std::vector<Contact>& list = contacts.contacts();
  for (std::size_t i = 0; i < list.size(); ++i) {
    list[i].active = was_active_[i] != 0;
    list[i].normal_multiplier = 0.0;
    list[i].friction_impulse.setZero();
  }
}

void RestingContacts::hold(std::vector<Eigen::Vector3d>& position,
                           std::vector<double>& inverse_mass) const {
  for (std::size_t k = 0; k < held_.size(); ++k) {
    position[held_[k]] = target_[k];
    inverse_mass[held_[k]] = 0.0;
  }
  keepOnFaces(position);
}

void RestingContacts::keepOnFaces(std::vector<Eigen::Vector3d>& position) const {
  for (const OnFace& f : on_face_) {
    Eigen::Vector3d& x = position[f.vertex];
    x -= (f.normal.dot(x) - f.offset) * f.normal;
  }
}

void RestingContacts::dropFaceNormals(std::vector<Eigen::Vector3d>& sum) const {
  for (const OnFace& f : on_face_) sum[f.vertex] -= f.normal.dot(sum[f.vertex]) * f.normal;
}

bool RestingContacts::accept(ContactSet& contacts, const std::vector<Eigen::Vector3d>& position,
                             const std::vector<Eigen::Vector3d>& predicted,
                             const std::vector<double>& inverse_mass, const EdgeSet& edges,
                             const std::vector<double>& multiplier, double tolerance,
                             bool linearized) {
  std::vector<Contact>& list = contacts.contacts();
  if (!linearized) contacts.linearize(position);
  // Each edge's impulse on its ends along its final direction (a pulls towards b), and the
  // other contacts' (rows of the fast iterations).
  other_impulse_.assign(position.size(), Eigen::Vector3d::Zero());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e) || multiplier[e] == 0.0) continue;
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    const Eigen::Vector3d d = position[b] - position[a];
    const double length = d.norm();
    if (!(length > 0.0)) continue;
    const Eigen::Vector3d impulse = (multiplier[e] / length) * d;
    other_impulse_[a] += impulse;
    other_impulse_[b] -= impulse;
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Contact& c = list[i];
    if (handled_[i] != 0) continue;
    other_impulse_[c.a] += (1.0 - c.t) * c.impulse();
    if (c.b != c.a) other_impulse_[c.b] += c.t * c.impulse();
  }
  bool holds = true;
  for (std::size_t i = 0; i < list.size() && holds; ++i) {
    const Contact& c = list[i];
    if (held_by_[c.a] != static_cast<std::int32_t>(i) || c.a != c.b) {
      // No row: it must not penetrate.
      holds = -c.gap <= tolerance * c.scale;
      continue;
    }
    // m (x - x~) = edge impulses + contact impulse.
    const Eigen::Vector3d impulse =
        (position[c.a] - predicted[c.a]) / inverse_mass[c.a] - other_impulse_[c.a];
    const double normal = c.normal.dot(impulse);
    holds = normal > 0.0 && std::abs(c.gap) <= tolerance * c.scale;
    // On a frictionless face the vertex moved within the face: no friction to bound.
    for (int k = 0; k < Contact::kFrictionDirections && holds && !on_face_mask_[c.a]; ++k) {
      holds = std::abs(c.tangent[k].dot(impulse)) <= c.friction * normal;
    }
  }
  if (!holds) return false;
  for (std::size_t i = 0; i < list.size(); ++i) {
    Contact& c = list[i];
    if (handled_[i] == 0) continue;  // a row: its impulse is the fast iterations'
    if (held_by_[c.a] != static_cast<std::int32_t>(i) || c.a != c.b) {
      c.active = false;
      c.normal_multiplier = 0.0;
      c.friction_impulse.setZero();
      continue;
    }
    const Eigen::Vector3d impulse =
        (position[c.a] - predicted[c.a]) / inverse_mass[c.a] - other_impulse_[c.a];
    c.active = true;
    c.normal_multiplier = c.normal.dot(impulse);
    if (on_face_mask_[c.a]) {
      c.friction_impulse.setZero();  // frictionless: its tangential part is the iterations'
    } else {
      c.friction_impulse = impulse - c.normal_multiplier * c.normal;
    }
  }
  return true;
}

}  // namespace yarn_tearing
