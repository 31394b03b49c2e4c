#include "yarn_tearing/core/projection/stiff_newton_step.hpp"

#include <algorithm>
#include <cmath>

#include "yarn_tearing/core/contact/sliding_friction_stiffness.hpp"

namespace yarn_tearing {
bool StiffNewtonStep::solve(const std::vector<Eigen::Vector3d>& predicted,
                            const std::vector<double>& inverse_mass, const EdgeSet& edges,
                            const EdgeIncidence& incidence, const EdgeStretchState& stretch_state,
                            const std::vector<std::uint8_t>& taut,
                            const std::vector<Eigen::Vector3d>& position,
                            const std::vector<double>& multiplier, const ContactSet* contacts) {
  const int rows = numberRows(inverse_mass, edges, incidence, taut, contacts);
  // A chain without contact rows is assembled straight into dense band storage; with them, whose
  // wraps are factorized near the round-off that decides where a wrap tears, on the sparse
  // LDL^T in natural order.
  dense_band_ = banded_ && contacts == nullptr;
  inverse_mass_ = &inverse_mass;
  condensing_ = false;
  with_contacts_ = contacts != nullptr;
  if (!banded_ && contacts == nullptr && start_.direction != nullptr && !force_full_) {
    chooseCondensation(edges, incidence, inverse_mass, rows);
  } else {
    last_eliminated_.clear();
  }
  if (lastFactorFits(contacts)) {
    if (reuse_wait_ > 0) {
      --reuse_wait_;
    } else if (solveWithLastFactor(rows, predicted, inverse_mass, edges, stretch_state, position,
                                   multiplier)) {
      reuse_backoff_ = 0;
      return true;
    } else {
      // Where systems change too fast for the last factors, try them ever more rarely.
      reuse_backoff_ = std::min(2 * reuse_backoff_ + 1, kMostReuseWait);
      reuse_wait_ = reuse_backoff_;
    }
  }
  last_factorization_.valid = false;
  last_solve_reused_ = false;
  const auto assemble = [&]() {
    triplets_.clear();
    if (dense_band_) dense_band_factorization_.begin(rows, chainBandwidth(edges));
    rhs_.setZero(rows);
    addVertexRows(predicted, inverse_mass, position);
    if (!addEdgeRows(edges, stretch_state, position, multiplier)) return false;
    if (condensing_) {
      condensation_.addCouplings(
          inverse_mass, edge_direction_,
          [this](int row, int col, double value) { addEntry(row, col, value); });
    }
    unsymmetric_ = false;
    if (contacts != nullptr) addContactRows(*contacts, inverse_mass, position);
    return true;
  };
  // Straight into the last analysed pattern where the entries list as in the last solve (a
  // fabric's rows, taut or idle, list the same entries while the taut set changes); otherwise
  // (a new layout, one cut short, sliding friction's LU, a refined solve's matrix) as triplets.
  direct_ = !banded_ && !refine_ &&
            generalFactorization().beginDirect(condensing_ ? condensation_.reducedRows() : rows);
  direct_listed_ = true;
  if (!assemble()) return false;
  if (direct_ && (!direct_listed_ || !generalFactorization().endDirect() || unsymmetric_)) {
    direct_fallbacks_ += unsymmetric_ ? 0 : 1;
    direct_ = false;
    if (!assemble()) return false;
  }
  direct_listings_ += direct_ ? 1 : 0;
  if (unsymmetric_) return solveUnsymmetric(rows);
  if (!solveSymmetric(rows)) return false;
  if (start_.direction == nullptr) return true;
  if (!banded_ && contacts == nullptr) rememberFactorization();
  return refineOnStartDirections(edges, position, inverse_mass, multiplier, stretch_state);
}

int StiffNewtonStep::numberRows(const std::vector<double>& inverse_mass, const EdgeSet& edges,
                                const EdgeIncidence& incidence,
                                const std::vector<std::uint8_t>& taut, const ContactSet* contacts) {
  // Rows in vertex order, each taut edge's row right after its later vertex's: a chain's system
  // is then banded, and the natural ordering factorizes it in O(N) without fill.
  // On other graphs every edge with a free end has a row, a slack or torn one an idle row
  // (m_e = 0, its couplings stored as zeros): the pattern then holds while the taut set changes
  // and as edges tear, and the factorization's symbolic analysis is kept (PatternCachedLdlt).
  const std::size_t n = inverse_mass.size();
  const bool fixed_pattern = !banded_;
  vertex_row_.assign(n, -1);
  edge_row_.assign(edges.size(), -1);
  idle_row_.assign(edges.size(), -1);
  int rows = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (inverse_mass[v] > 0.0) {
      vertex_row_[v] = rows;
      rows += 3;
    }
    for (const std::uint32_t* it = incidence.begin(v); it != incidence.end(v); ++it) {
      const std::uint32_t e = *it;
      if (std::max(edges.vertex_a[e], edges.vertex_b[e]) != v) continue;
      if (taut[e]) {
        edge_row_[e] = rows++;
      } else if (fixed_pattern &&
                 (inverse_mass[edges.vertex_a[e]] > 0.0 || inverse_mass[edges.vertex_b[e]] > 0.0)) {
        idle_row_[e] = rows++;
      }
    }
    if (contacts == nullptr) continue;
    for (std::uint32_t k = contact_start_[v]; k < contact_start_[v + 1]; ++k) {
      const std::uint32_t i = contact_order_[k];
      const Contact& c = contacts->contacts()[i];
      // A point on a held vertex only (t at its end) cannot be moved: no rows.
      const bool movable_point = c.mobility(inverse_mass) > 0.0;
      normal_row_[i] = c.active && movable_point ? rows++ : -1;
      for (int k = 0; k < Contact::kFrictionDirections; ++k) {
        const bool sticks =
            normal_row_[i] >= 0 && hasFriction(c) && c.friction_sign[k] == 0 && slide_only_[i] == 0;
        friction_row_[i][k] = sticks ? rows++ : -1;
      }
    }
  }
  return rows;
}

void StiffNewtonStep::chooseCondensation(const EdgeSet& edges, const EdgeIncidence& incidence,
                                         const std::vector<double>& inverse_mass, int rows) {
  system_row_.resize(edges.size());
  plain_.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    system_row_[e] = edge_row_[e] >= 0 ? edge_row_[e] : idle_row_[e];
    const bool plain_a = inverse_mass[edges.vertex_a[e]] == 0.0 || takesStartDirection(e, false);
    const bool plain_b = inverse_mass[edges.vertex_b[e]] == 0.0 || takesStartDirection(e, true);
    // By the ends' directions alone, taut or idle: the same vertices are eliminated, and the
    // reduced system keeps its pattern, while the taut set changes. A torn edge stiffens nothing.
    plain_[e] = (plain_a && plain_b) || !edges.intact(e);
  }
  const bool any =
      condensation_.choose(edges, incidence, vertex_row_, system_row_, plain_, rows) > 0;
  same_eliminated_ = condensation_.eliminated() == last_eliminated_
                         ? std::min(same_eliminated_ + 1, kCondensedAfterSolves)
                         : 0;
  condensing_ = any && same_eliminated_ >= kCondensedAfterSolves;
  last_eliminated_ = condensation_.eliminated();
}

bool StiffNewtonStep::lastFactorFits(const ContactSet* contacts) const {
  const LastFactorization& last = last_factorization_;
  return last.valid && !force_fresh_ && !banded_ && contacts == nullptr &&
         start_.direction != nullptr && !refine_ && last.condensed == condensing_ &&
         last.vertex_row == vertex_row_ && last.edge_row == edge_row_ &&
         last.idle_row == idle_row_ &&
         (!condensing_ || last.eliminated == condensation_.eliminated());
}

void StiffNewtonStep::rememberFactorization() {
  LastFactorization& last = last_factorization_;
  last.valid = true;
  last.condensed = condensing_;
  last.vertex_row = vertex_row_;
  last.edge_row = edge_row_;
  last.idle_row = idle_row_;
  if (condensing_) last.eliminated = condensation_.eliminated();
}

bool StiffNewtonStep::solveWithLastFactor(int rows, const std::vector<Eigen::Vector3d>& predicted,
                                          const std::vector<double>& inverse_mass,
                                          const EdgeSet& edges,
                                          const EdgeStretchState& stretch_state,
                                          const std::vector<Eigen::Vector3d>& position,
                                          const std::vector<double>& multiplier) {
  rhs_only_ = true;
  rhs_.setZero(rows);
  addVertexRows(predicted, inverse_mass, position);
  const bool assembled = addEdgeRows(edges, stretch_state, position, multiplier);
  rhs_only_ = false;
  if (!assembled) return false;
  // A projection's first Newton step after a solve that the last factors took too (a scene that
  // changes slowly) starts its multipliers where the linearization's are, the last step's: the
  // vertex moves, a small difference of the large inertial and constraint terms, are then not
  // computed from the factors' error in those terms. Later Newton steps (a step that did not
  // converge in one: the scene jerks) and others start from zero, whose residual is the
  // right-hand side.
  const bool warm = last_solve_reused_ && newton_steps_ == 1;
  solution_.setZero(rows);
  if (warm) {
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (edge_row_[e] >= 0) solution_[edge_row_[e]] = multiplier[e];
    }
  }
  double last_change = 0.0;  // the last pass's correction [mixed units]
  for (int pass = 0; pass < kReusePasses; ++pass) {
    const bool from_zero = pass == 0 && !warm;
    if (!from_zero) exactResidual(edges, position, inverse_mass, multiplier, stretch_state);
    if (!solveAssembled(from_zero ? rhs_ : residual_, correction_)) return false;
    solution_ += correction_;
    const double change = correction_.lpNorm<Eigen::Infinity>();
    const double goal = kReuseTolerance * solution_.lpNorm<Eigen::Infinity>();
    if (change <= goal) {
      last_solve_reused_ = solution_.allFinite();
      return last_solve_reused_;
    }
    // A correction that does not shrink: the factors are too far off.
    if (pass > 0 && !(change < last_change)) return false;
    last_change = change;
  }
  return false;
}

void StiffNewtonStep::skipIdleEntries(int ra, int rb) {
  // addEdgeRows' entries of an edge with these vertex rows: a 3 x 3 block on each end's
  // diagonal, two coupling the ends, and each end's three couplings with the edge row, both ways.
  const int ends = (ra >= 0 ? 1 : 0) + (rb >= 0 ? 1 : 0);
  const int blocks = ends + (ends == 2 ? 2 : 0);
  const auto count = static_cast<std::size_t>(9 * blocks + 6 * ends);
  direct_listed_ = direct_listed_ && generalFactorization().skipDirect(count);
}

void StiffNewtonStep::addBlock(int row, int col, const Eigen::Matrix3d& block) {
  if (rhs_only_) return;
  if (listsDirectly()) {
    // addEntry()'s path chosen once for the nine entries, straight into the analysed pattern (a
    // fabric's Newton systems, whose geometric stiffness blocks are most of their entries).
    direct_listed_ = direct_listed_ && generalFactorization().addDirectBlock(row, col, block);
    return;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) addEntry(row + i, col + j, block(i, j));
  }
}

int StiffNewtonStep::chainBandwidth(const EdgeSet& edges) const {
  // The farthest below the diagonal an edge's entries reach: its row from its first vertex's,
  // its geometric stiffness from one vertex's rows to the other's.
  int bandwidth = 2;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int re = edge_row_[e];
    if (re < 0) continue;
    const int ra = vertex_row_[edges.vertex_a[e]];
    const int rb = vertex_row_[edges.vertex_b[e]];
    const int first = ra >= 0 ? ra : rb;
    if (first >= 0) bandwidth = std::max(bandwidth, re - first);
    if (ra >= 0 && rb >= 0) bandwidth = std::max(bandwidth, std::abs(rb - ra) + 2);
  }
  return bandwidth;
}

void StiffNewtonStep::addVertexRows(const std::vector<Eigen::Vector3d>& predicted,
                                    const std::vector<double>& inverse_mass,
                                    const std::vector<Eigen::Vector3d>& position) {
  const bool fixed_pattern = !banded_;
  for (std::size_t v = 0; v < position.size(); ++v) {
    const int r = vertex_row_[v];
    if (r < 0) continue;
    const double mass = 1.0 / inverse_mass[v];
    if (fixed_pattern) addBlock(r, r, Eigen::Matrix3d::Zero());
    for (int i = 0; i < 3; ++i) addEntry(r + i, r + i, mass);
    rhs_.segment<3>(r) = -mass * (position[v] - predicted[v]);
  }
}

bool StiffNewtonStep::addEdgeRows(const EdgeSet& edges, const EdgeStretchState& stretch_state,
                                  const std::vector<Eigen::Vector3d>& position,
                                  const std::vector<double>& multiplier) {
  edge_direction_.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const bool idle = idle_row_[e] >= 0;
    if (!idle && edge_row_[e] < 0) continue;
    const int ra = vertex_row_[edges.vertex_a[e]];
    const int rb = vertex_row_[edges.vertex_b[e]];
    Eigen::Vector3d dir = Eigen::Vector3d::Zero();
    Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
    int re = idle_row_[e];
    double diagonal = -1.0;  // an idle row: -1 m_e = 0, its couplings stored as zeros
    if (!idle) {
      const Eigen::Vector3d d = position[edges.vertex_b[e]] - position[edges.vertex_a[e]];
      const double length = d.norm();
      if (!(length > 0.0)) return false;
      dir = d / length;
      // Geometric stiffness m_e Hess C_e = m_e (I - n n^T) / l on the (a, b) blocks; none
      // where both ends take their start directions (or are supports) in a condensed system.
      if (!condensing_ || !plain_[e]) {
        g = (multiplier[e] / length) * (Eigen::Matrix3d::Identity() - dir * dir.transpose());
      }
      re = edge_row_[e];
      diagonal = -stretch_state.shift()[e];
      rhs_[re] = -(length - stretch_state.baseLength()[e]);
    }
    edge_direction_[e] = dir;
    if (idle && listsDirectly()) {
      // Its entries are zeros but its diagonal: passed over in the analysed sequence, the
      // diagonal listed (which checks that the row is where the sequence has it).
      skipIdleEntries(ra, rb);
      addEntry(re, re, diagonal);
      continue;
    }
    // A taut and an idle row list the same entries in the same order, so that the pattern
    // (PatternCachedLdlt) holds while the taut set changes.
    if (ra >= 0) addBlock(ra, ra, g);
    if (rb >= 0) addBlock(rb, rb, g);
    if (ra >= 0 && rb >= 0) {
      addBlock(ra, rb, -g);
      addBlock(rb, ra, -g);
    }
    for (int i = 0; i < 3; ++i) {
      if (ra >= 0) {
        addEntry(re, ra + i, -dir[i]);
        addEntry(ra + i, re, -dir[i]);
      }
      if (rb >= 0) {
        addEntry(re, rb + i, dir[i]);
        addEntry(rb + i, re, dir[i]);
      }
    }
    addEntry(re, re, diagonal);
  }
  return true;
}

void StiffNewtonStep::assembleMatrix(int rows) {
  matrix_.resize(rows, rows);
  matrix_.setFromTriplets(triplets_.begin(), triplets_.end());
}

bool StiffNewtonStep::solveUnsymmetric(int rows) {
  // Sliding friction couples its normal multiplier into the vertex rows only.
  assembleMatrix(rows);
  ++factorizations_;
  sliding_factorization_.lu.compute(matrix_);
  if (sliding_factorization_.lu.info() != Eigen::Success) return false;
  solution_ = sliding_factorization_.lu.solve(rhs_);
  if (!refine_) return solution_.allFinite();
  return refine([this](const Eigen::VectorXd& rhs, Eigen::VectorXd& result) {
    result = sliding_factorization_.lu.solve(rhs);
    return result.allFinite();
  });
}

bool StiffNewtonStep::solveSymmetric(int rows) {
  // The dense band keeps its own copy of the matrix (refine()).
  if ((banded_ && !dense_band_) || (refine_ && !banded_)) assembleMatrix(rows);
  ++factorizations_;
  if (dense_band_) {
    if (!dense_band_factorization_.factorize()) return false;
  } else if (banded_) {
    sparse_band_factorization_.ldlt.compute(matrix_);
    if (sparse_band_factorization_.ldlt.info() != Eigen::Success) return false;
  } else if (direct_) {
    if (!generalFactorization().factorizeDirect()) return false;
  } else {
    // The idle rows' stored zeros stay out of the elimination: they only keep the pattern.
    PatternCachedLdlt& factorization = generalFactorization();
    factorization.leaveOutZeros();
    const int size = condensing_ ? condensation_.reducedRows() : rows;
    if (!factorization.factorize(triplets_, size)) return false;
  }
  if (!solveAssembled(rhs_, solution_)) return false;
  return !refine_ || refine([this](const Eigen::VectorXd& rhs, Eigen::VectorXd& result) {
    return solveAssembled(rhs, result);
  });
}

bool StiffNewtonStep::refineOnStartDirections(const EdgeSet& edges,
                                              const std::vector<Eigen::Vector3d>& position,
                                              const std::vector<double>& inverse_mass,
                                              const std::vector<double>& multiplier,
                                              const EdgeStretchState& stretch_state) {
  // Ends that take the start direction make the exact system unsymmetric; the symmetric one
  // (current directions everywhere) differs from it by the small turn of each such edge in one
  // step and by the geometric stiffness of slow vertices, (omega dt)^2 <= 1/4: refine on it.
  for (int pass = 0; pass < kRefinementPasses; ++pass) {
    exactResidual(edges, position, inverse_mass, multiplier, stretch_state);
    if (!solveAssembled(residual_, correction_)) return false;
    solution_ += correction_;
    if (correction_.lpNorm<Eigen::Infinity>() <= 1e-12 * solution_.lpNorm<Eigen::Infinity>()) {
      break;
    }
  }
  return solution_.allFinite();
}

bool StiffNewtonStep::solveAssembled(const Eigen::VectorXd& rhs, Eigen::VectorXd& result) {
  if (dense_band_) {
    dense_band_factorization_.solve(rhs, result);
    return result.allFinite();
  }
  if (banded_) {
    result = sparse_band_factorization_.ldlt.solve(rhs);
    return sparse_band_factorization_.ldlt.info() == Eigen::Success && result.allFinite();
  }
  if (condensing_) {
    condensation_.condense(rhs, *inverse_mass_, edge_direction_, reduced_rhs_);
    reduced_solution_ = condensed_factorization_.solve(reduced_rhs_);
    condensation_.expand(rhs, reduced_solution_, *inverse_mass_, edge_direction_, result);
    return result.allFinite();
  }
  result = generalFactorization().solve(rhs);
  return result.allFinite();
}

bool StiffNewtonStep::takesStartDirection(std::size_t e, bool end_b) const {
  if (start_.direction == nullptr) return false;
  return end_b ? (*start_.at_b)[e] != 0 : (*start_.at_a)[e] != 0;
}

void StiffNewtonStep::exactResidual(const EdgeSet& edges,
                                    const std::vector<Eigen::Vector3d>& position,
                                    const std::vector<double>& inverse_mass,
                                    const std::vector<double>& multiplier,
                                    const EdgeStretchState& stretch_state) {
  residual_ = rhs_;
  const auto move = [&](int row) -> Eigen::Vector3d {
    return row >= 0 ? Eigen::Vector3d(solution_.segment<3>(row)) : Eigen::Vector3d::Zero();
  };
  for (std::size_t v = 0; v < position.size(); ++v) {
    const int r = vertex_row_[v];
    if (r >= 0) residual_.segment<3>(r) -= solution_.segment<3>(r) / inverse_mass[v];
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int re = edge_row_[e];
    if (re < 0) continue;
    const int ra = vertex_row_[edges.vertex_a[e]];
    const int rb = vertex_row_[edges.vertex_b[e]];
    const Eigen::Vector3d d = position[edges.vertex_b[e]] - position[edges.vertex_a[e]];
    const double length = d.norm();
    const Eigen::Vector3d dir = d / length;
    const Eigen::Vector3d relative = move(rb) - move(ra);
    const Eigen::Vector3d stiffness =
        (multiplier[e] / length) * (relative - dir * dir.dot(relative));
    const double force = solution_[re];
    // An end that takes the start direction feels the force along it, with no geometric
    // stiffness (the direction does not move with the vertices).
    if (ra >= 0) {
      if (takesStartDirection(e, false)) {
        residual_.segment<3>(ra) += force * (*start_.direction)[e];
      } else {
        residual_.segment<3>(ra) += stiffness + force * dir;
      }
    }
    if (rb >= 0) {
      if (takesStartDirection(e, true)) {
        residual_.segment<3>(rb) -= force * (*start_.direction)[e];
      } else {
        residual_.segment<3>(rb) -= stiffness + force * dir;
      }
    }
    residual_[re] -= dir.dot(relative) - stretch_state.shift()[e] * force;
  }
}

double StiffNewtonStep::linearizedStretch(const EdgeSet& edges,
                                          const EdgeStretchState& stretch_state, std::size_t e,
                                          const std::vector<Eigen::Vector3d>& position) const {
  const std::uint32_t a = edges.vertex_a[e];
  const std::uint32_t b = edges.vertex_b[e];
  const Eigen::Vector3d d = position[b] - position[a];
  const double length = d.norm();
  if (!(length > 0.0)) return 0.0;
  Eigen::Vector3d move = Eigen::Vector3d::Zero();
  if (vertex_row_[b] >= 0) move += solution_.segment<3>(vertex_row_[b]);
  if (vertex_row_[a] >= 0) move -= solution_.segment<3>(vertex_row_[a]);
  return length - stretch_state.baseLength()[e] + (d / length).dot(move);
}

void StiffNewtonStep::apply(const std::vector<Eigen::Vector3d>& predicted,
                            const std::vector<double>& inverse_mass, const EdgeSet& edges,
                            const EdgeIncidence& incidence, EdgeStretchState& stretch_state,
                            const std::vector<std::uint8_t>& movable,
                            std::vector<std::uint8_t>& taut, std::vector<Eigen::Vector3d>& position,
                            std::vector<double>& multiplier, ContactSet* contacts,
                            const StartDirections& start) {
  start_ = start;
  ++newton_steps_;
  for (std::size_t e = 0; e < edges.size(); ++e) taut[e] = taut[e] & movable[e];
  if (contacts != nullptr) {
    rememberImpulses(*contacts);
    sortContacts(*contacts, position.size());
    friction_flips_.assign(contacts->contacts().size(), 0);
    normal_flips_.assign(contacts->contacts().size(), 0);
    slide_only_.assign(contacts->contacts().size(), 0);
  }
  banded_ = true;
  for (std::size_t e = 0; e < edges.size() && banded_; ++e) {
    banded_ = edges.vertex_b[e] == edges.vertex_a[e] + 1;
  }
  pass_multiplier_.resize(edges.size());
  stretch_.resize(edges.size());
  frontier_.reset(edges.size());
  leaves_.assign(edges.size(), 0);
  released_move_.assign(edges.size(), 0.0);
  // Block principal pivoting, as in the fast iterations: release the taut edges that would
  // push, take in the slack ones that the step would stretch (with the taut frontier), solve
  // again. On a contact-free graph that is no chain, the first kQuickNewtonSteps solve once:
  // the next linearization takes its taut set from this step's multipliers and stretches
  // (stoppedEarly()).
  const bool quick =
      !banded_ && contacts == nullptr && !full_pivoting_ && newton_steps_ <= kQuickNewtonSteps;
  stopped_early_ = false;
  for (int pass = 0;; ++pass) {
    if (!solve(predicted, inverse_mass, edges, incidence, stretch_state, taut, position, multiplier,
               contacts)) {
      return;
    }
    if (pass == kMaxPivotingPasses) break;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      pass_multiplier_[e] = edge_row_[e] >= 0 ? solution_[edge_row_[e]] : 0.0;
      // A push that would move the edge's ends by less than the slack tolerance counts as none,
      // as a stretch below it does for a slack edge: an edge at zero force (round-off either
      // side) would leave and come back in every step.
      if (pass_multiplier_[e] < 0.0 &&
          pushMove(inverse_mass, edges, e) <= slack_tolerance_ * edges.rest_length[e]) {
        pass_multiplier_[e] = 0.0;
      }
    }
    frontier_.beginPass(movable, taut, pass_multiplier_);
    bool changed = false;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (!movable[e]) continue;
      if (taut[e]) {
        if (pass_multiplier_[e] < 0.0 && frontier_.mayLeave(e) && leaves_[e] < kMostLeaves) {
          ++leaves_[e];
          released_move_[e] = pushMove(inverse_mass, edges, e);
          taut[e] = 0;
          frontier_.left(e);
          stretch_state.release(edges, e);
          changed = true;
        } else if (pass_multiplier_[e] > 0.0 && stretch_state.wouldSwitch(e, pass_multiplier_[e])) {
          stretch_state.settle(edges, e, pass_multiplier_[e]);
          changed = true;
        }
        continue;
      }
      stretch_[e] = linearizedStretch(edges, stretch_state, e, position);
      if (stretch_[e] > slack_tolerance_ * edges.rest_length[e]) {
        taut[e] = 1;
        frontier_.joined(e);
        changed = true;
      }
    }
    if (contacts != nullptr && pivotContacts(*contacts, inverse_mass, position)) changed = true;
    if (!changed) break;
    if (quick) {
      stopped_early_ = true;
      break;
    }
    frontier_.grow(edges, incidence, movable, stretch_, taut);
  }
  if (contacts != nullptr) {
    storeContactImpulses(*contacts);
    measureImpulseChange(*contacts, inverse_mass);
  }
  for (std::size_t v = 0; v < position.size(); ++v) {
    if (vertex_row_[v] >= 0) position[v] += solution_.segment<3>(vertex_row_[v]);
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    multiplier[e] = edge_row_[e] >= 0 ? std::max(solution_[edge_row_[e]], 0.0) : 0.0;
  }
}

void StiffNewtonStep::addContactRows(const ContactSet& contacts,
                                     const std::vector<double>& inverse_mass,
                                     const std::vector<Eigen::Vector3d>& position) {
  for (std::size_t i = 0; i < contacts.contacts().size(); ++i) {
    const Contact& c = contacts.contacts()[i];
    const int ra = vertex_row_[c.a];
    const int rb = c.b != c.a ? vertex_row_[c.b] : -1;
    const double wa = 1.0 - c.t;
    const double wb = c.t;
    const double shift = compliance_ * (wa * wa * inverse_mass[c.a] + wb * wb * inverse_mass[c.b]);
    // Row r of gradient -(wa d, wb d) on (a, b), C = -d . (p - q), right-hand side -C.
    const auto row = [&](int r, const Eigen::Vector3d& d, double rhs) {
      for (int k = 0; k < 3; ++k) {
        if (ra >= 0) {
          addEntry(r, ra + k, -wa * d[k]);
          addEntry(ra + k, r, -wa * d[k]);
        }
        if (rb >= 0) {
          addEntry(r, rb + k, -wb * d[k]);
          addEntry(rb + k, r, -wb * d[k]);
        }
      }
      addEntry(r, r, -shift);
      rhs_[r] = rhs;
    };
    if (normal_row_[i] >= 0) {
      row(normal_row_[i], c.normal, c.gap);
      // Geometric stiffness of the push on a curved surface, m_n Hess C = -m_n Hess(distance):
      // without it a light vertex pressed onto a post by a taut wrap buzzes sideways and grows.
      if (c.normal_multiplier > 0.0) {
        const Eigen::Matrix3d h = -c.normal_multiplier * contacts.curvature(c, position);
        if (ra >= 0) addBlock(ra, ra, wa * wa * h);
        if (rb >= 0) addBlock(rb, rb, wb * wb * h);
        if (ra >= 0 && rb >= 0) {
          addBlock(ra, rb, wa * wb * h);
          addBlock(rb, ra, wa * wb * h);
        }
        // The closest point moving along a turning segment: -m_n times the Hessian's second
        // part (ContactSet::closestPointTurn). Without it a segment pivoting about a point it
        // keeps on the surface looks free, cuts into the solid, and is pushed out one step late:
        // a wrap gained energy at every step.
        Eigen::Matrix<double, 6, 1> turn;
        double second = 0.0;
        if (contacts.closestPointTurn(c, position, turn, second)) {
          const Eigen::Matrix<double, 6, 6> g =
              (c.normal_multiplier / second) * turn * turn.transpose();
          if (ra >= 0) addBlock(ra, ra, g.topLeftCorner<3, 3>());
          if (rb >= 0) addBlock(rb, rb, g.bottomRightCorner<3, 3>());
          if (ra >= 0 && rb >= 0) {
            addBlock(ra, rb, g.topRightCorner<3, 3>());
            addBlock(rb, ra, g.bottomLeftCorner<3, 3>());
          }
        }
      }
    }
    if (normal_row_[i] < 0 || !hasFriction(c)) continue;
    // Sticking tangents hold the point where it stuck; a sliding one pushes with +-mu m_n,
    // m_n the normal row's own multiplier: a column coupling the two (the system becomes
    // unsymmetric, solved by LU), so that the bound is exact in every solve.
    const Eigen::Vector3d slip = c.point(position) - c.anchor();
    Eigen::Vector3d sliding = Eigen::Vector3d::Zero();
    for (int k = 0; k < Contact::kFrictionDirections; ++k) {
      if (friction_row_[i][k] >= 0) {
        row(friction_row_[i][k], c.tangent[k], c.tangent[k].dot(slip));
      } else {
        sliding += (c.friction_sign[k] * c.friction) * c.tangent[k];
      }
    }
    if (sliding.isZero()) continue;
    // A point that slides along one tangent and sticks along the other has slipped far from its
    // anchor: the sticking row's tangent turning with the segment and the surface changes the
    // row by s . d tau_k, which its gradient needs (the system is unsymmetric here anyway).
    for (int k = 0; k < Contact::kFrictionDirections; ++k) {
      const int r = friction_row_[i][k];
      Eigen::Vector3d on_a;
      Eigen::Vector3d on_b;
      if (r < 0 || !stickingRowTurn(contacts, c, k, slip, position, on_a, on_b)) continue;
      for (int j = 0; j < 3; ++j) {
        if (ra >= 0) addEntry(r, ra + j, on_a[j]);
        if (rb >= 0) addEntry(r, rb + j, on_b[j]);
      }
    }
    unsymmetric_ = true;
    const int rn = normal_row_[i];
    for (int k = 0; k < 3; ++k) {
      if (ra >= 0) addEntry(ra + k, rn, -wa * sliding[k]);
      if (rb >= 0) addEntry(rb + k, rn, -wb * sliding[k]);
    }
    // The sliding impulse turns with the segment and the surface: its derivative (as the edges'
    // geometric stiffness), without which a fast slide's Newton steps converge only linearly.
    double slide[Contact::kFrictionDirections];
    for (int k = 0; k < Contact::kFrictionDirections; ++k) {
      slide[k] = friction_row_[i][k] < 0 ? c.friction_sign[k] * c.friction : 0.0;
    }
    SlidingFrictionStiffness blocks;
    if (!slidingFrictionStiffness(contacts, c, slide, position, blocks)) continue;
    if (ra >= 0) addBlock(ra, ra, blocks.aa);
    if (rb >= 0) addBlock(rb, rb, blocks.bb);
    if (ra >= 0 && rb >= 0) {
      addBlock(ra, rb, blocks.ab);
      addBlock(rb, ra, blocks.ba);
    }
  }
}

void StiffNewtonStep::sortContacts(const ContactSet& contacts, std::size_t num_vertices) {
  const std::vector<Contact>& list = contacts.contacts();
  normal_row_.assign(list.size(), -1);
  friction_row_.assign(list.size(), {-1, -1});
  contact_start_.assign(num_vertices + 1, 0);
  for (const Contact& c : list) ++contact_start_[std::max(c.a, c.b) + 1];
  for (std::size_t v = 0; v < num_vertices; ++v) contact_start_[v + 1] += contact_start_[v];
  contact_order_.resize(list.size());
  contact_fill_.assign(contact_start_.begin(), contact_start_.end() - 1);
  for (std::uint32_t i = 0; i < list.size(); ++i) {
    contact_order_[contact_fill_[std::max(list[i].a, list[i].b)]++] = i;
  }
}

bool StiffNewtonStep::hasFriction(const Contact& c) { return c.friction > 0.0 && c.friction_known; }

void StiffNewtonStep::slideAlongSlip(std::size_t i, Contact& c,
                                     const std::vector<Eigen::Vector3d>& position,
                                     const Eigen::Vector3d& move) {
  // Pushing without friction instead would let a wrap sliding by 0.4 chord per step at
  // dt 1e-4 keep its energy: the points that take over the push as the chords pass the post
  // are those that flip, and frictionless they would let its kinetic energy up to 2.2x the capstan
  // law's bound). Along a tangent that carries less than kSlideShare of the slip, none.
  slide_only_[i] = 1;
  const Eigen::Vector3d slip = c.point(position) + move - c.anchor();
  double largest = 0.0;
  for (int k = 0; k < Contact::kFrictionDirections; ++k) {
    largest = std::max(largest, std::abs(c.tangent[k].dot(slip)));
  }
  for (int k = 0; k < Contact::kFrictionDirections; ++k) {
    const double along = c.tangent[k].dot(slip);
    const bool slips =
        std::abs(along) > kSlackTolerance * c.scale && std::abs(along) >= kSlideShare * largest;
    c.friction_sign[k] = slips ? (along > 0.0 ? -1 : 1) : 0;
  }
}

Eigen::Vector3d StiffNewtonStep::frictionImpulse(std::size_t i, const Contact& c) const {
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
  if (normal_row_[i] < 0 || !hasFriction(c)) return impulse;
  const double bound = c.friction * solution_[normal_row_[i]];
  for (int k = 0; k < Contact::kFrictionDirections; ++k) {
    const int r = friction_row_[i][k];
    impulse += (r >= 0 ? solution_[r] : c.friction_sign[k] * bound) * c.tangent[k];
  }
  return impulse;
}

Eigen::Vector3d StiffNewtonStep::pointMove(const Contact& c) const {
  Eigen::Vector3d move = Eigen::Vector3d::Zero();
  if (vertex_row_[c.a] >= 0) move += (1.0 - c.t) * solution_.segment<3>(vertex_row_[c.a]);
  if (c.b != c.a && vertex_row_[c.b] >= 0) move += c.t * solution_.segment<3>(vertex_row_[c.b]);
  return move;
}

bool StiffNewtonStep::pivotContacts(ContactSet& contacts, const std::vector<double>& inverse_mass,
                                    const std::vector<Eigen::Vector3d>& position) {
  bool changed = false;
  std::vector<Contact>& list = contacts.contacts();
  for (std::size_t i = 0; i < list.size(); ++i) {
    Contact& c = list[i];
    const Eigen::Vector3d move = pointMove(c);
    const double mobility = c.mobility(inverse_mass);
    if (!c.active && c.enabled && mobility > 0.0) {
      // Taken in when the step would push the point into the obstacle (with the friction
      // states it had: those of the last step where it touched then, else frictionless until
      // it has a normal force).
      if (c.gap + c.normal.dot(move) < -kSlackTolerance * c.scale) {
        c.active = true;
        // A point with friction that left and came back too often in this Newton step slides
        // along its slip for the rest of it: its friction rows made the pass cycle (a point
        // that carries almost nothing between two that carry the wrap).
        if (++normal_flips_[i] >= kMaxNormalFlips) slideAlongSlip(i, c, position, move);
        changed = true;
      }
      continue;
    }
    // Impulse [kg m] that moves the point by kSlackTolerance of its scale: smaller multipliers
    // and friction excesses are round-off, and switching on them would only chatter.
    if (!c.active || !(mobility > 0.0) || normal_row_[i] < 0) continue;
    const double negligible = kSlackTolerance * c.scale / mobility;
    const double normal = solution_[normal_row_[i]];
    if (normal < -negligible) {
      // It would pull: the point leaves the obstacle.
      c.active = false;
      ++normal_flips_[i];
      c.friction_impulse.setZero();
      changed = true;
      continue;
    }
    if (!hasFriction(c)) continue;
    const double bound = c.friction * std::max(normal, 0.0);
    // A point whose states flipped too often in this Newton step only starts to slide
    // (kMaxFrictionFlips): its friction never exceeds the bound.
    const bool may_stick = friction_flips_[i] < kMaxFrictionFlips &&
                           newton_steps_ <= kStickingNewtonSteps && slide_only_[i] == 0;
    // The point's slip over the step after this solve, from where it stuck [m].
    const Eigen::Vector3d slip = c.point(position) + move - c.anchor();
    for (int k = 0; k < Contact::kFrictionDirections; ++k) {
      std::int8_t& sign = c.friction_sign[k];
      const int r = friction_row_[i][k];
      if (sign == 0) {
        // Sticking needs more than the bound: it slides, friction at the bound against the pull.
        if (r >= 0 && std::abs(solution_[r]) > bound * (1.0 + kFrictionMargin) + negligible) {
          sign = solution_[r] > 0.0 ? 1 : -1;
          ++friction_flips_[i];
          changed = true;
        }
      } else if (may_stick && sign * c.tangent[k].dot(slip) > kSlackTolerance * c.scale) {
        // Friction would drive the point instead of opposing its slip: it sticks.
        sign = 0;
        ++friction_flips_[i];
        changed = true;
      }
    }
  }
  return changed;
}

void StiffNewtonStep::rememberImpulses(const ContactSet& contacts) {
  previous_impulse_.clear();
  for (const Contact& c : contacts.contacts()) previous_impulse_.push_back(c.impulse());
}

void StiffNewtonStep::measureImpulseChange(const ContactSet& contacts,
                                           const std::vector<double>& inverse_mass) {
  impulse_change_ = 0.0;
  const std::vector<Contact>& list = contacts.contacts();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Contact& c = list[i];
    // Relative to the impulse, or to the one that would move the free point by its length scale
    // where that is larger (a point barely touching).
    const double mobility = c.mobility(inverse_mass);
    if (!(mobility > 0.0)) continue;
    const double size = std::max(c.impulse().norm(), c.scale / mobility);
    impulse_change_ = std::max(impulse_change_, (c.impulse() - previous_impulse_[i]).norm() / size);
  }
}

void StiffNewtonStep::storeContactImpulses(ContactSet& contacts) const {
  std::vector<Contact>& list = contacts.contacts();
  for (std::size_t i = 0; i < list.size(); ++i) {
    Contact& c = list[i];
    c.normal_multiplier = normal_row_[i] >= 0 ? std::max(solution_[normal_row_[i]], 0.0) : 0.0;
    c.friction_impulse = frictionImpulse(i, c);
    c.friction_known = c.friction_known || c.normal_multiplier > 0.0;
  }
}

}  // namespace yarn_tearing
