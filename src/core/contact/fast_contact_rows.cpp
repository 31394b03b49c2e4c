#include "yarn_tearing/core/contact/fast_contact_rows.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace yarn_tearing {

bool FastContactRows::select(const ContactSet& contacts, const std::vector<std::uint8_t>& skip,
                             const std::vector<double>& inverse_mass) {
  row_.clear();
  const std::vector<Contact>& list = contacts.contacts();
  std::size_t points = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Contact& c = list[i];
    if (skip[i] != 0 || !(c.mobility(inverse_mass) > 0.0)) continue;
    // Friction in the fast iterations only while it sticks: a sliding point, or one whose
    // states are not known yet (new in this step), takes the Newton steps.
    const bool friction = c.friction > 0.0;
    if (friction && (!c.friction_known || c.friction_sign[0] != 0 || c.friction_sign[1] != 0)) {
      return false;
    }
    if (++points > kMaxPoints) return false;
    Row r;
    r.contact = static_cast<std::uint32_t>(i);
    r.normal = static_cast<std::uint32_t>(row_.size());
    r.scale = c.scale;
    r.a = c.a;
    r.b = c.b;
    r.active = c.active;
    row_.push_back(r);
    for (int k = 0; friction && k < Contact::kFrictionDirections; ++k) {
      r.tangent = k;
      row_.push_back(r);
    }
  }
  reset();
  return true;
}

bool FastContactRows::touches(const std::vector<std::uint8_t>& vertex_mask) const {
  return std::any_of(row_.begin(), row_.end(),
                     [&](const Row& r) { return vertex_mask[r.a] != 0 || vertex_mask[r.b] != 0; });
}

void FastContactRows::reset() {
  multiplier_.assign(row_.size(), 0.0);
  pass_multiplier_.assign(row_.size(), 0.0);
  target_.assign(row_.size(), 0.0);
}

void FastContactRows::linearize(const ContactSet& contacts,
                                const std::vector<Eigen::Vector3d>& position) {
  for (Row& r : row_) {
    const Contact& c = contacts.contacts()[r.contact];
    r.weight_a = c.a != c.b ? 1.0 - c.t : 1.0;
    r.weight_b = c.a != c.b ? c.t : 0.0;
    if (r.tangent < 0) {
      r.direction = c.normal;
      r.value = -c.gap;
      // A box's segment point handed to its end's vertex contact (ContactSet::linearize).
      if (!c.enabled) r.active = false;
    } else {
      r.direction = c.tangent[r.tangent];
      r.value = -r.direction.dot(c.point(position) - c.anchor());
    }
  }
}

void FastContactRows::addGradients(const std::vector<double>& value,
                                   std::vector<Eigen::Vector3d>& sum) const {
  for (std::size_t j = 0; j < row_.size(); ++j) {
    if (value[j] == 0.0) continue;
    const Row& r = row_[j];
    sum[r.a] -= (r.weight_a * value[j]) * r.direction;
    if (r.b != r.a) sum[r.b] -= (r.weight_b * value[j]) * r.direction;
  }
}

void FastContactRows::multiply(const std::vector<double>& inverse_mass,
                               const std::vector<Eigen::Vector3d>& sum,
                               std::vector<double>& product) const {
  product.resize(row_.size());
  for (std::size_t j = 0; j < row_.size(); ++j) {
    const Row& r = row_[j];
    double p = -r.weight_a * inverse_mass[r.a] * r.direction.dot(sum[r.a]);
    if (r.b != r.a) p -= r.weight_b * inverse_mass[r.b] * r.direction.dot(sum[r.b]);
    product[j] = p;
  }
}

void FastContactRows::setTargets(const std::vector<double>& product) {
  for (std::size_t j = 0; j < row_.size(); ++j) target_[j] = row_[j].value + product[j];
}

double FastContactRows::coupling(const Row& i, const Row& j,
                                 const std::vector<double>& inverse_mass) const {
  double k = 0.0;
  const double d = i.direction.dot(j.direction);
  for (int end = 0; end < i.ends(); ++end) {
    const std::uint32_t v = end == 0 ? i.a : i.b;
    const double wi = end == 0 ? i.weight_a : i.weight_b;
    double wj = 0.0;
    if (v == j.a) wj += j.weight_a;
    if (v == j.b && j.b != j.a) wj += j.weight_b;
    k += inverse_mass[v] * wi * wj * d;
  }
  return k;
}

void FastContactRows::solve(const EdgeSet& edges, EdgeGramSolver& gram, const GramSystem& system,
                            const std::vector<double>& inverse_mass, std::vector<double>& step) {
  // Edges alone: m0 = K_ee^-1 t_e.
  gram.solve(edges, system, step);
  active_rows_.clear();
  for (std::uint32_t j = 0; j < row_.size(); ++j) {
    pass_multiplier_[j] = 0.0;
    if (row_[j].active) active_rows_.push_back(j);
  }
  const std::size_t k = active_rows_.size();
  if (k == 0) return;
  const std::vector<Eigen::Vector3d>& direction = *system.direction;
  const std::vector<std::uint8_t>& active_edge = *system.active;
  column_.resize(k);
  solved_.resize(k);
  schur_.resize(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  schur_rhs_.resize(static_cast<Eigen::Index>(k));
  for (std::size_t p = 0; p < k; ++p) {
    // K_e,row = g_e . W G_row over the active edges meeting the row's vertices.
    const Row& r = row_[active_rows_[p]];
    std::vector<double>& column = column_[p];
    column.assign(edges.size(), 0.0);
    for (int end = 0; end < r.ends(); ++end) {
      const std::uint32_t v = end == 0 ? r.a : r.b;
      const double weight = end == 0 ? r.weight_a : r.weight_b;
      const Eigen::Vector3d gradient = -(inverse_mass[v] * weight) * r.direction;
      const EdgeIncidence& incidence = gram.incidence();
      for (const std::uint32_t* it = incidence.begin(v); it != incidence.end(v); ++it) {
        const std::uint32_t e = *it;
        if (!active_edge[e]) continue;
        const double sign = edges.vertex_b[e] == v ? 1.0 : -1.0;
        column[e] += sign * direction[e].dot(gradient);
      }
    }
    solved_[p] = column;
    gram.resolve(edges, system, solved_[p]);  // K_ee as factorized for m0
  }
  for (std::size_t p = 0; p < k; ++p) {
    const Row& r = row_[active_rows_[p]];
    double rhs = target_[active_rows_[p]];
    for (std::size_t e = 0; e < edges.size(); ++e) rhs -= column_[p][e] * step[e];
    schur_rhs_[static_cast<Eigen::Index>(p)] = rhs;
    for (std::size_t q = 0; q < k; ++q) {
      double s = coupling(r, row_[active_rows_[q]], inverse_mass);
      for (std::size_t e = 0; e < edges.size(); ++e) s -= column_[p][e] * solved_[q][e];
      schur_(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(q)) = s;
    }
    const double mobility = r.weight_a * r.weight_a * inverse_mass[r.a] +
                            (r.b != r.a ? r.weight_b * r.weight_b * inverse_mass[r.b] : 0.0);
    schur_(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p)) +=
        kContactCompliance * mobility;
  }
  const Eigen::VectorXd mu = schur_.ldlt().solve(schur_rhs_);
  for (std::size_t p = 0; p < k; ++p) {
    const double m = mu[static_cast<Eigen::Index>(p)];
    pass_multiplier_[active_rows_[p]] = m;
    for (std::size_t e = 0; e < edges.size(); ++e) step[e] -= solved_[p][e] * m;
  }
}

bool FastContactRows::pivot(const std::vector<double>& product, double tolerance) {
  bool changed = false;
  for (std::size_t j = 0; j < row_.size(); ++j) {
    Row& r = row_[j];
    if (r.tangent >= 0) continue;
    const bool was = r.active;
    if (r.active && pass_multiplier_[j] < 0.0) {
      r.active = false;  // it would pull: the point leaves the obstacle
    } else if (!r.active && target_[j] - product[j] > tolerance * r.scale) {
      r.active = true;  // the step would push it in
    }
    if (r.active == was) continue;
    changed = true;
    for (std::size_t t = j + 1; t < row_.size() && row_[t].normal == j; ++t)
      row_[t].active = r.active;
  }
  return changed;
}

void FastContactRows::accept(const std::vector<double>& inverse_mass,
                             std::vector<Eigen::Vector3d>& position) {
  for (std::size_t j = 0; j < row_.size(); ++j) {
    const Row& r = row_[j];
    const double total = r.tangent < 0 ? std::max(pass_multiplier_[j], 0.0) : pass_multiplier_[j];
    const double change = total - multiplier_[j];
    multiplier_[j] = total;
    if (change == 0.0) continue;
    position[r.a] += (inverse_mass[r.a] * r.weight_a * change) * r.direction;
    if (r.b != r.a) position[r.b] += (inverse_mass[r.b] * r.weight_b * change) * r.direction;
  }
}

void FastContactRows::store(ContactSet& contacts) const {
  for (std::size_t j = 0; j < row_.size(); ++j) {
    const Row& r = row_[j];
    Contact& c = contacts.contacts()[r.contact];
    if (r.tangent < 0) {
      c.normal_multiplier = multiplier_[j];
      c.active = r.active;
      c.friction_impulse.setZero();
    } else {
      c.friction_impulse += multiplier_[j] * r.direction;
    }
  }
}

bool FastContactRows::frictionHolds(const ContactSet& contacts) const {
  for (std::size_t j = 0; j < row_.size(); ++j) {
    const Row& r = row_[j];
    if (r.tangent < 0) continue;
    const double bound = contacts.contacts()[r.contact].friction * multiplier_[r.normal];
    if (std::abs(multiplier_[j]) > bound) return false;
  }
  return true;
}

}  // namespace yarn_tearing
